// SPDX-License-Identifier: MIT
/// @file
/// The pole sampler's marginal of each order of a fit (inference/residue_evidence.hpp), built once per order and
/// kept for the whole fit: every missed-mode check (after the first round, after each re-run round, after each
/// growth step, and for the final warnings; docs/method.md, "Model selection") evaluates the same marginals, and
/// building one (the Gram points of the data) is most of the cost of a check.
#pragma once

#include "data/measurement.hpp"
#include "inference/residue_evidence.hpp"
#include "model/order.hpp"
#include "selection/fit.hpp"
#include "selection/reduced_model.hpp"

#include <map>
#include <memory>
#include <utility>

namespace admitgen {

class OrderMarginals {
 public:
  /// `data` must outlive this object.
  OrderMarginals(const Measurement& data, DataCount count, double admittance_scale);

  /// The marginal of `order`, built on first use. Not thread-safe (a ResidueEvidence holds work buffers).
  const ResidueEvidence& of(const Order& order);
  /// The marginal's peak over `model`'s run (marginal_peak), kept until the run changes (a re-run merged into
  /// it: its calls, live points or ln Z differ).
  const MarginalPeak& peak(const ModelResult& model);

 private:
  struct Entry {
    std::unique_ptr<ResidueEvidence> evidence;
    MarginalPeak peak;
    long calls = -1;  ///< the run the peak was taken over (calls, live points, ln Z), −1: none yet
    int live = -1;
    double log_z = 0.0;
  };
  Entry& entry(const Order& order);

  const Measurement& data_;
  DataCount count_;
  double scale_;
  std::map<std::pair<int, int>, Entry> entries_;  ///< by (Q, S)
};

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The slice proposal (inference/proposal.hpp): a copy of a random surviving live point (it already satisfies
/// L > L*) moved by a chain of slice moves along its cluster's whitened axes (inference/slice_step.hpp; PolyChord,
/// Handley et al. 2015; dynesty's "rslice"). It never gives up. Each cluster of live points keeps its own slice
/// width, which starts at every covariance update from the geometric mean of the previous widths.
#pragma once

#include "inference/model.hpp"
#include "inference/proposal.hpp"
#include "inference/slice_step.hpp"

#include <vector>

namespace admitgen {

class SliceProposal final : public Proposal {
 public:
  /// `slices` 1-D moves per replacement.
  SliceProposal(const Model& model, int slices);

  void update(const LivePoints& live, const LivePointClusters& clusters) override;
  bool propose(const LivePoints& live, Eigen::Index worst, double log_l_min, long max_calls, Rng& rng,
               ProposedPoint& out, long& calls) override;

  /// Running mean of a chain's likelihood calls (weight 0.1 to the newest; 4 calls per slice at the start).
  double mean_calls() const { return mean_calls_; }

 private:
  const Model& model_;
  int slices_;
  double mean_calls_;
  SliceStep step_;
  const LivePointClusters* clusters_ = nullptr;
  std::vector<double> widths_;  ///< per cluster
};

}  // namespace admitgen

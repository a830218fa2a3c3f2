// SPDX-License-Identifier: MIT
/// @file
/// The passive estimate of a fitted order (docs/passivity.md, "Passive estimate"). For each of the
/// highest-likelihood posterior samples (kCandidates of them), keep its poles and take the residues that
/// fit the data best (the likelihood's own unweighted least squares) among those that make Re G(jω) ≥ 0
/// at every ω (passivity/passive_residues.hpp); a sample that is already passive is kept as it is. The
/// estimate is the candidate with the highest likelihood after this step.
/// It is what `emit` uses by default: a filter that is passive by construction, at the smallest possible
/// cost in fit for those poles.
#pragma once

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "model/order.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen::passivity {

struct PassiveEstimate {
  /// Candidates tried: poles of the best samples differ little, but where the best sample's residues
  /// violate passivity strongly a slightly worse sample can be much better once made passive.
  static constexpr int kCandidates = 16;
  static constexpr const char* kPolesFrom =
      "the best (after the passive residue refit) of the 16 highest-likelihood posterior samples";
  int candidate_rank = 0;                    ///< 0 = the highest-likelihood sample
  Eigen::VectorXd theta;                     ///< packed as model/order.hpp
  double log_likelihood = 0.0;               ///< ln L of theta (inference/likelihood.hpp)
  double relative_rms_residual = 0.0;        ///< √(Σ|D − G|² / Σ|D|²) of theta
  double best_sample_relative_rms_residual = 0.0;  ///< the same for the highest-likelihood sample
  double best_sample_log_likelihood = 0.0;
  bool certified = false;                    ///< Hamiltonian test: Re G ≥ 0 for every ω
  double min_re = 0.0;                       ///< minimum of Re G found by the certificate's scan
  int rounds = 0;                            ///< constraint-generation rounds
  bool changed = false;                      ///< false when the best sample was already passive and kept
};

/// `candidates`: samples of the order in descending likelihood (θ packed as model/order.hpp); the first
/// kCandidates are tried. changed = false when the chosen one was passive as sampled.
PassiveEstimate passive_estimate(const Measurement& data, const Order& order,
                                 const std::vector<Eigen::VectorXd>& candidates, DataCount count);

/// Share of data points with Re y < 0 (a passive wall has Re y ≥ 0) and the most negative Re y.
struct DataPassivity {
  int negative_points = 0;
  double min_re = 0.0;
};
DataPassivity data_passivity(const Measurement& data);

}  // namespace admitgen::passivity

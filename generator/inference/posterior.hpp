// SPDX-License-Identifier: MIT
/// @file
/// Posterior summaries from a nested-sampling run: weights p_i = L_i ΔX_i / Z, weighted moments,
/// weighted quantiles, and deterministic equal-weight resampling for predictive bands.
#pragma once

#include "core/rng.hpp"
#include "inference/nested_sampler.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen {

struct ParameterSummary {
  std::string name;
  double mean;
  double std;
  double ci95_lo;  ///< 2.5 % weighted quantile
  double ci95_hi;  ///< 97.5 % weighted quantile
  double max_likelihood;
};

/// Normalised posterior weights of every point of the run (sum to 1).
Eigen::ArrayXd posterior_weights(const NestedRun& run);

/// Kish effective sample size (Σp)²/Σp².
double effective_sample_size(const Eigen::ArrayXd& weights);

/// Weighted quantile q ∈ [0,1] of values (linear in the cumulative weight at the midpoints); points of
/// zero weight are skipped.
double weighted_quantile(const Eigen::ArrayXd& values, const Eigen::ArrayXd& weights, double q);

/// Summary of each parameter; `names` has run.dim entries.
std::vector<ParameterSummary> summarize(const NestedRun& run, const std::vector<std::string>& names);

/// Indices of `count` equal-weight draws by systematic resampling (Kitagawa 1996): one uniform offset.
/// Never returns a point of zero weight.
std::vector<std::size_t> resample_indices(const Eigen::ArrayXd& weights, std::size_t count, Rng& rng);

/// Index of the highest-likelihood point.
std::size_t max_likelihood_index(const NestedRun& run);

}  // namespace admitgen

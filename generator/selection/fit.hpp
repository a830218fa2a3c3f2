/// @file
/// Order selection over the grid Q ∈ [0, qmax] × S ∈ [0, smax]: one nested-sampling run per order
/// (in parallel over orders, each order with its own seed stream so results do not depend on the
/// thread count), Bayes factors, the selection rule, the selected order's parameter summaries and
/// its posterior predictive band of G(ω) and α(f).
#pragma once

#include "core/progress.hpp"
#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/posterior.hpp"
#include "inference/priors.hpp"
#include "model/order.hpp"
#include "selection/selection_rule.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen {

struct FitSettings {
  int qmax = 3;
  int smax = 3;
  NestedSettings sampler;  ///< live, dlogz, max_iterations, slices, seed (the user seed)
  PriorRanges priors = PriorRanges::table1();
  std::string priors_origin = "table1";  ///< "table1" or the prior file's path
  bool reduce_symmetry = true;
  DataCount data_count = DataCount::two_per_point;
  SelectionRule rule = SelectionRule::best();
  int threads = 0;  ///< 0 = hardware concurrency
};

struct ModelResult {
  Order order;
  NestedRun run;
  double seconds = 0.0;
  std::vector<ParameterSummary> parameters;  ///< folded to the reduced form
};

/// Posterior predictive band at the data frequencies: 2.5 %, 50 %, 97.5 % quantiles.
struct PredictiveBand {
  Eigen::ArrayXd f_hz;
  Eigen::ArrayXd re_lo, re_median, re_hi;
  Eigen::ArrayXd im_lo, im_median, im_hi;
  Eigen::ArrayXd alpha_lo, alpha_median, alpha_hi;
  int draws = 0;
};

struct FitResult {
  std::vector<ModelResult> models;  ///< grid order (Q-major)
  std::size_t selected = 0;
  PredictiveBand predictive;        ///< of the selected order
};

/// Seed of the run for `order`, derived from the user seed (independent of grid and thread count).
std::uint64_t order_seed(std::uint64_t user_seed, const Order& order);

/// Runs one order: nested sampling plus folded summaries.
ModelResult fit_order(const Measurement& data, const Order& order, const FitSettings& settings,
                      const NestedProgressFn& progress = {});

/// Runs the whole grid and selects. Throws InputError if the data cannot constrain the largest order.
FitResult run_fit(const Measurement& data, const FitSettings& settings, Progress& progress);

/// Predictive band from `draws` equal-weight posterior draws (deterministic given the seed).
PredictiveBand predictive_band(const Measurement& data, const ModelResult& model, int draws, std::uint64_t seed);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// What a fit will cost, stated before it starts (`admitgen fit` prints it; `--cost-only` stops there).
/// Nested sampling replaces each dead point with a slice walk of (3 + dim) one-dimensional slices, and the
/// number of iterations grows with live points × information; over the bundled fits (samples/fits,
/// samples/synthetic: live 100 and 500, dim 1-15, 200-1025 points) the likelihood evaluations of one order
/// were 15-51 × live × dim × (3 + dim) (the last factor is the slices per step, --slices), 19-36 × over a
/// whole fit. The pole sampler (dim = Q + 2S) took 5-24 × live × dim × (3 + dim) on the reference file and
/// Basotect round 10 cm (more for an over-complete order whose spare pair wanders, Q0S3 of the reference file 106);
/// its estimate takes 15 (whole fits: the golden fit 0.55×, the reference grid at 500 live 1.7×, round 10 cm at 100
/// live 1.2× of it), and times the closed-form marginal instead of the likelihood. The full sampler's takes 27, so a whole fit's count is right within a factor ~2 on those fits;
/// missed-mode re-runs and the passive truncation come on top. One evaluation is timed here, at the largest order, on the data as read; it costs in
/// proportion to points × (1 + Q + S).
#pragma once

#include "data/measurement.hpp"
#include "selection/fit.hpp"

#include <string>

namespace admitgen {

struct FitCostEstimate {
  long points = 0;
  int orders = 0;
  double evaluations = 0.0;            ///< likelihood evaluations over every order
  double seconds_per_evaluation = 0.0;  ///< measured at the largest order
  double cpu_seconds = 0.0;            ///< evaluations × their cost, each order at its own size
  double longest_order_seconds = 0.0;  ///< one order runs on one thread
  int threads = 1;                     ///< workers over orders (at most one per order)
  double wall_seconds = 0.0;           ///< max(cpu / threads, the longest order)
  double growth_cpu_seconds = 0.0;     ///< at most this much more if the grid grows (its budget); 0 without growth
  /// One line, e.g. "cost estimate: 100000 points, 16 orders: ~2.1e+08 likelihood evaluations at ...".
  std::string describe() const;
};

/// Likelihood evaluations that one order is expected to take at `live` live points (the model above).
double expected_evaluations(const Order& order, const FitSettings& settings, int live);
/// Its expected work: those evaluations, each in proportion to 1 + Q + S (the pole terms per point). The unit is
/// one evaluation of a one-term model; the comparison driver's time left is estimated from it.
double expected_work(const Order& order, const FitSettings& settings, int live);

/// Times the largest order's likelihood on `data` (a few evaluations, at least 20 ms) and applies the
/// model above.
FitCostEstimate estimate_fit_cost(const Measurement& data, const FitSettings& settings);

}  // namespace admitgen

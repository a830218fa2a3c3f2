// SPDX-License-Identifier: MIT
/// @file
/// Growing the order grid when the data ask for it (docs/method.md, "Growing the grid"). When the selected
/// order lies on the grid's edge (Q = qmax or S = smax) and the evidence still rises across that edge (its
/// ln Z exceeds that of the order with one pole of that kind fewer by more than kGrowthMarginNats and by
/// more than 3 combined errors), the next larger order of that kind might be better still: the grid gains
/// the row Q = qmax + 1 (every S of the grid) or the column S = smax + 1 (every Q), or both, and selection
/// runs again. An edge at Q = 0 or S = 0 (a kind the grid leaves out) never grows. Growth stops when the selected order lies inside the grid, or when a
/// limit refuses it; the result then says which, and a selection on the edge becomes a warning.
///
/// Limits (all deterministic, so equal inputs and seed give equal grids whatever the thread count):
///   - at most `FitSettings::grid_growth` extra real poles and as many extra pairs beyond qmax/smax;
///   - the largest order must keep fewer parameters than real data values (as for the grid itself);
///   - a budget of likelihood calls: the estimated calls of every added order together at most the
///     first round's calls or kMinGrowthBudgetCalls, whichever is larger (so growth at most doubles a fit
///     that is not already short). An added order of dimension D is estimated at c·(D/d)² from the largest
///     fitted order (c calls, dimension d): a run's iterations grow with
///     its information H, roughly ∝ dimension, and its calls per iteration with its slices per replacement,
///     3 + dimension (docs/method.md, "Growing the grid").
#pragma once

#include "model/order.hpp"
#include "selection/fit.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace admitgen {

/// 10 dB, "strong" on Jeffreys' scale: the gain of the last pole across the edge that makes growth worth trying.
inline constexpr double kGrowthMarginNats = 2.302585092994046;

/// The smallest budget of likelihood calls for growth: about 5-30 s of CPU at 1-6 µs per call.
inline constexpr double kMinGrowthBudgetCalls = 5e6;

/// One growth step: the orders to add and the grid after it.
struct GridStep {
  std::vector<Order> add;  ///< the new orders, Q-major
  int qmax = 0, smax = 0;  ///< the grid after the step
  double calls = 0.0;      ///< the added orders' estimated likelihood calls together (the budget's measure)
  std::string reason;      ///< e.g. "Q3S3 lies on the edge S = smax = 3: added S = 4 for Q0-3"
};

/// The next growth step of a fit whose grid is Q0-qmax × S0-smax, or nullopt with `refusal` set to why the
/// selected order stays on the edge (empty when it lies inside the grid). `spent_calls` are the estimated
/// calls of the steps already taken, `budget_calls` the budget for all of them together.
std::optional<GridStep> next_grid_step(const std::vector<ModelResult>& models, std::size_t selected, int qmax,
                                       int smax, const FitSettings& settings, int real_data_values,
                                       double spent_calls, double budget_calls, std::string& refusal);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Growing the set of fitted orders when the data ask for it (docs/method.md, "Growing the grid"). When the
/// selected order (Q, S) lies on the edge of the fitted orders in Q (Q + 1 with the same S not fitted) or in S,
/// and the evidence still rises across that edge (its ln Z exceeds that of the order with one pole of that kind
/// fewer by more than kGrowthMarginNats and by more than 3 combined errors), the next larger order of that kind
/// might be better still: the orders next to the selected one across the edge are added (Q + 1 or S + 1, and at
/// a corner both and Q + 1, S + 1), and selection runs again. This is a stepwise search around the selection,
/// as Hyndman & Khandakar's for ARIMA orders (J. Stat. Softw. 27(3), 2008), not a whole new row and column:
/// the orders far from the selection along the new edge (few poles of one kind, many of the other) cost as much
/// as the ones next to it and lie thousands of dB below. An edge at Q = 0 or S = 0 (a kind the grid leaves out)
/// never grows. Growth stops when the selected order has fitted neighbours across every rising edge, or when a
/// limit refuses it; the result then says which, and a selection on the edge becomes a warning. A hole next to
/// the selection (the order with one pole of a kind fewer not fitted: nothing says whether that kind still
/// rises) is not followed but stated in that warning.
///
/// Limits (all deterministic, so equal inputs and seed give equal grids whatever the thread count):
///   - at most `FitSettings::grid_growth` extra real poles and as many extra pairs beyond qmax/smax;
///   - the largest order must keep fewer parameters than real data values (as for the grid itself);
///   - a budget of work, counted in pole passes (one real pole or one pair over one data point, the unit of the
///     marginal likelihood's cost: inference/residue_gram.hpp): the estimated passes of every added order
///     together at most the first round's or kMinGrowthBudgetPasses, whichever is larger (so growth at most
///     doubles a fit that is not already short). An added order is estimated at c·(D/d)² calls from the largest
///     fitted order (c calls, dimension d), each call N·(1 + Q + S) passes: a run's iterations grow with its
///     information H, roughly ∝ dimension, and its calls per iteration with its slices per replacement, which
///     grow with the dimension (docs/method.md, "Growing the grid").
#pragma once

#include "core/progress.hpp"
#include "data/measurement.hpp"
#include "model/order.hpp"
#include "passivity/passive_estimate.hpp"
#include "selection/fit.hpp"
#include "selection/order_marginals.hpp"
#include "selection/order_runs.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace admitgen {

/// 10 dB, "strong" on Jeffreys' scale: the gain of the last pole across the edge that makes growth worth trying.
inline constexpr double kGrowthMarginNats = 2.302585092994046;

/// The smallest budget of growth, in pole passes: about 60 s of CPU at the 2.3 ns per pass that the closed-form
/// marginal takes on 1025 points at Q4S4 (`bench_fit --order Q4S4 --basotect`, AMD EPYC, AVX-512).
inline constexpr double kSecondsPerPolePass = 2.3e-9;
inline constexpr double kMinGrowthBudgetPasses = 60.0 / kSecondsPerPolePass;

/// Pole passes of `calls` likelihood calls of `order` on `points` data points (the budget's measure).
double pole_passes(const Order& order, double calls, long points);

/// One growth step: the orders to add.
struct GridStep {
  std::vector<Order> add;  ///< the new orders, Q-major
  double passes = 0.0;     ///< the added orders' estimated pole passes together (the budget's measure)
  std::string reason;      ///< e.g. "Q3S3 lies on the corner of the fitted orders (…): added Q4S3, Q3S4, Q4S4"
};

/// The next growth step of a fit that has fitted `models`, or nullopt with `refusal` set to why the selected
/// order stays on the edge (empty when it has fitted neighbours across every rising edge). `spent_passes` are
/// the estimated passes of the steps already taken, `budget_passes` the budget for all of them together.
std::optional<GridStep> next_grid_step(const std::vector<ModelResult>& models, std::size_t selected,
                                       const FitSettings& settings, int real_data_values, long points,
                                       double spent_passes, double budget_passes, std::string& refusal);

/// Grows `orders` while the selected order lies on their edge, its passive estimate misses the accuracy target
/// and more poles might reach it (selection/accuracy_stop.hpp, target_out_of_reach): runs the added orders and the
/// re-runs they call for, and estimates every order's passive model. `would_grow` is set when the target (met or
/// out of reach) stopped a growth the evidence asked for; the result's `edge` is then empty (a note, not a
/// warning).
GridGrowth grow_grid(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                     OrderMarginals& marginals, double first_round_passes, const passivity::LazyPassiveBound& bound,
                     bool& would_grow, Progress& progress);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The nested-sampling runs of a fit's orders (docs/method.md, "Model selection"): each order's first run, made of
/// FitSettings::runs independent parts on seed streams of their own and merged (inference/run_merge.hpp), and the
/// re-run rounds of orders that missed a mode, merged into the order's run. fit_order (selection/fit.hpp) is one
/// order's first run; these run many on the comparison driver (inference/comparison.hpp), largest first.
#pragma once

#include "core/progress.hpp"
#include "data/measurement.hpp"
#include "model/order.hpp"
#include "selection/fit.hpp"
#include "selection/order_marginals.hpp"

#include <cstddef>
#include <vector>

namespace admitgen {

/// The orders a fit has run, Q-major, with one result each and the last re-run round each ran (0: none).
struct FittedOrders {
  std::vector<Order> grid;
  std::vector<ModelResult> results;
  std::vector<int> rounds;
};

/// Throws InputError when FitSettings::runs leaves an order's first runs fewer than 5 live points each.
void check_runs(const FitSettings& settings);

/// First runs of orders.grid[i] for i in `which`, written to orders.results[i].
void run_orders(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                const std::vector<std::size_t>& which, Progress& progress);

/// `add` (orders not yet fitted) run and inserted into `orders`, which stays Q-major.
void add_orders(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                const std::vector<Order>& add, Progress& progress);

/// Re-runs the orders that missed a mode (missed_modes, on `marginals`), in rounds r = 1 … missed_mode_retries:
/// round r adds 2^r runs of half the live points each, on streams of their own, to the order's run and merges
/// them with it, so that after round r it holds about 2^r times the live points, as one run of that many would,
/// at half the calls of such a run and with its parts in parallel. With FitSettings::runs ≥ 2, orders whose runs
/// disagree are re-run too. An order runs round r at most once (FittedOrders::rounds), so calling this again after
/// the grid grew re-runs only what the new orders reveal. An order without poles (its evidence analytic) has no
/// mode to miss.
void rerun_missed_modes(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                        OrderMarginals& marginals, Progress& progress);

}  // namespace admitgen

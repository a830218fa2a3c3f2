// SPDX-License-Identifier: MIT
#include "selection/grid_growth.hpp"

#include "core/errors.hpp"
#include "inference/evidence.hpp"
#include "selection/accuracy_stop.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace admitgen {
namespace {

/// Estimated likelihood calls of `order`: c·(D/d)² from the largest fitted order (most calls among equals), see
/// the header.
double estimated_calls(const std::vector<ModelResult>& models, const Order& order) {
  const ModelResult* from = &models.front();
  for (const auto& m : models)
    if (m.order.dim() > from->order.dim() || (m.order.dim() == from->order.dim() && m.run.calls > from->run.calls))
      from = &m;
  const double ratio = static_cast<double>(order.dim()) / static_cast<double>(from->order.dim());
  return static_cast<double>(from->run.calls) * ratio * ratio;
}

/// Whether the evidence still rises across the selected order's edge of kind `kind` ('Q' or 'S'): its ln Z
/// exceeds that of the order with one pole of that kind fewer (`inner`) by the margin of the header. Never at
/// Q = 0 / S = 0. When that order was not fitted (growth around the selection leaves such holes, e.g. Q2S5 next to
/// an added Q3S5), nothing says whether the evidence still rises: `hole`, which growth does not follow (it would
/// cost a larger order on no evidence) but which the result states.
struct Rise {
  bool rising = false, hole = false;
  Order inner{0, 0};                    ///< the order with one pole of the kind fewer
  const ModelResult* fit = nullptr;     ///< its result, when fitted
};

/// The fitted result of `order`, or nullptr.
const ModelResult* find_fitted(const std::vector<ModelResult>& models, const Order& order) {
  const auto it = std::find_if(models.begin(), models.end(), [&](const ModelResult& m) { return m.order == order; });
  return it == models.end() ? nullptr : &*it;
}

Rise rise_across(const std::vector<ModelResult>& models, const ModelResult& chosen, char kind) {
  const int q = chosen.order.q() - (kind == 'Q' ? 1 : 0), s = chosen.order.s() - (kind == 'S' ? 1 : 0);
  if (q < 0 || s < 0) return {};
  const Order inner(q, s);
  const ModelResult* fit = find_fitted(models, inner);
  if (fit == nullptr) return {false, true, inner, nullptr};
  const double margin = std::max(kGrowthMarginNats, 3.0 * std::hypot(chosen.run.log_z_error, fit->run.log_z_error));
  return {chosen.run.log_z > fit->run.log_z + margin, false, inner, fit};
}

/// The refusal's note on holes next to the selection, e.g. "Q2S5, one real pole fewer than Q3S5, was not fitted,
/// so whether the evidence still rises with real poles is not known".
std::string hole_text(const Order& chosen, const Rise& q_rise, const Rise& s_rise) {
  std::string out;
  for (const auto& [rise, kind] : {std::pair{q_rise, 'Q'}, std::pair{s_rise, 'S'}}) {
    if (!rise.hole) continue;
    out += fmt::format("{}{}, one {} fewer than {}, was not fitted, so whether the evidence still rises with more "
                       "{} is not known",
                       out.empty() ? "" : "; ", rise.inner.name(), kind == 'Q' ? "real pole" : "pair", chosen.name(),
                       kind == 'Q' ? "real poles" : "pairs");
  }
  return out;
}

}  // namespace

double pole_passes(const Order& order, double calls, long points) {
  return calls * static_cast<double>(points) * static_cast<double>(1 + order.q() + order.s());
}

std::optional<GridStep> next_grid_step(const std::vector<ModelResult>& models, std::size_t selected,
                                       const FitSettings& settings, int real_data_values, long points,
                                       double spent_passes, double budget_passes, std::string& refusal) {
  refusal.clear();
  const ModelResult& best = models.at(selected);
  const Order chosen = best.order;
  const auto fitted = [&](const Order& o) { return find_fitted(models, o) != nullptr; };
  const Order q_next(chosen.q() + 1, chosen.s()), s_next(chosen.q(), chosen.s() + 1);
  const Rise q_rise = fitted(q_next) ? Rise{} : rise_across(models, best, 'Q');
  const Rise s_rise = fitted(s_next) ? Rise{} : rise_across(models, best, 'S');
  const bool q_edge = q_rise.rising, s_edge = s_rise.rising;
  const std::string holes = hole_text(chosen, q_rise, s_rise);
  // A refusal also states the holes next to the selection.
  const auto refuse = [&](std::string why) {
    refusal = holes.empty() ? std::move(why) : why.empty() ? holes + "; larger orders were not tried" : why + "; " + holes;
    return std::nullopt;
  };
  if (!q_edge && !s_edge) return refuse("");
  const std::string edge = q_edge && s_edge ? "the corner" : q_edge ? "the edge in Q" : "the edge in S";
  const int q_cap = settings.qmax + settings.grid_growth, s_cap = settings.smax + settings.grid_growth;
  const bool grow_q = q_edge && q_next.q() <= q_cap && q_next.q() <= Order::kMaxPoles;
  const bool grow_s = s_edge && s_next.s() <= s_cap && s_next.s() <= Order::kMaxPoles;
  if (!grow_q && !grow_s) {
    return refuse(fmt::format("{} lies on {} of the fitted orders and the grid may not grow further ({} = {}); "
                              "larger orders were not tried",
                              chosen.name(), edge, setting("grid_growth"), settings.grid_growth));
  }
  GridStep step;
  const Order largest(chosen.q() + (grow_q ? 1 : 0), chosen.s() + (grow_s ? 1 : 0));
  for (const Order& o : order_grid(largest.q(), largest.s()))
    if (o.q() >= chosen.q() && o.s() >= chosen.s() && o != chosen && !fitted(o)) step.add.push_back(o);
  if (largest.dim() + 2 > real_data_values) {
    return refuse(fmt::format("{} lies on {} of the fitted orders; growing to {} would need more than the K = {} real "
                              "data values; larger orders were not tried",
                              chosen.name(), edge, largest.name(), real_data_values));
  }
  for (const Order& o : step.add) step.passes += pole_passes(o, estimated_calls(models, o), points);
  if (spent_passes + step.passes > budget_passes) {
    std::string names;
    for (const Order& o : step.add) names += (names.empty() ? "" : ", ") + o.name();
    return refuse(fmt::format("{} lies on {} of the fitted orders; fitting {} would cost about {:.3g} G pole passes "
                              "(about {:.0f} s of CPU), beyond the budget ({:.3g} G left of {:.3g} G); larger orders "
                              "were not tried (raise {}/{} to include them)",
                              chosen.name(), edge, names, 1e-9 * step.passes, step.passes * kSecondsPerPolePass,
                              1e-9 * std::max(0.0, budget_passes - spent_passes), 1e-9 * budget_passes,
                              setting("qmax"), setting("smax")));
  }
  std::string added, gains;
  for (const Order& o : step.add) added += (added.empty() ? "" : ", ") + o.name();
  for (const Rise& rise : {q_rise, s_rise})
    if (rise.rising)
      gains += fmt::format("{}{:.1f} dB over {}", gains.empty() ? "" : ", ", deciban(best.run.log_z, rise.fit->run.log_z),
                           rise.fit->order.name());
  step.reason = fmt::format("{} lies on {} of the fitted orders ({}): added {}", chosen.name(), edge, gains, added);
  return step;
}

GridGrowth grow_grid(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                     OrderMarginals& marginals, double first_round_passes, const passivity::LazyPassiveBound& bound,
                     bool& would_grow, Progress& progress) {
  GridGrowth growth{settings.qmax, settings.smax, {}, {}};
  const int k = real_data_count(settings.data_count, data.size());
  const double budget = std::max(first_round_passes, kMinGrowthBudgetPasses);
  double spent = 0.0;
  for (;;) {
    estimate_passive(data, settings, orders.results, bound);
    const std::size_t selected = select_usable(settings, orders.results);
    const ModelResult& chosen = orders.results[selected];
    auto step = next_grid_step(orders.results, selected, settings, k, static_cast<long>(data.size()), spent, budget,
                               growth.edge);
    if (step && settings.max_buffers > 0) {
      const auto over = [&](const Order& o) { return o.buffers() > settings.max_buffers; };
      step->add.erase(std::remove_if(step->add.begin(), step->add.end(), over), step->add.end());
      if (step->add.empty()) {
        growth.edge = fmt::format("{} lies on the edge of the fitted orders and the evidence still rises, but the "
                                  "next orders exceed the budget of {} buffers per node ({})",
                                  chosen.order.name(), settings.max_buffers, setting("max_buffers"));
        step.reset();
      }
    }
    // The target met, or out of reach of more poles (its warning says why): larger orders are not fitted, and
    // what they would add is a note, not a warning.
    if ((chosen.accuracy && chosen.accuracy->meets) || !target_out_of_reach(data, settings, chosen, bound).empty()) {
      would_grow = step.has_value() || !growth.edge.empty();
      growth.edge.clear();
      return growth;
    }
    if (!step) return growth;
    progress.message(step->reason);
    growth.steps.push_back(step->reason);
    spent += step->passes;
    for (const Order& o : step->add) {
      growth.qmax = std::max(growth.qmax, o.q());
      growth.smax = std::max(growth.smax, o.s());
    }
    add_orders(data, settings, orders, step->add, progress);
    rerun_missed_modes(data, settings, orders, marginals, progress);
  }
}

}  // namespace admitgen

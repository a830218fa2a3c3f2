// SPDX-License-Identifier: MIT
#include "selection/grid_growth.hpp"

#include "core/errors.hpp"
#include "inference/evidence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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

/// The order inside the grid next to the selected one across its edge of kind `kind` ('Q' or 'S'), when the
/// evidence still rises across that edge: the selected ln Z exceeds that order's by the margin of the header.
/// nullptr otherwise, and always at Q = 0 / S = 0.
const ModelResult* rising_from(const std::vector<ModelResult>& models, const ModelResult& chosen, char kind) {
  const int q = chosen.order.q() - (kind == 'Q' ? 1 : 0), s = chosen.order.s() - (kind == 'S' ? 1 : 0);
  if (q < 0 || s < 0) return nullptr;
  const auto inner = std::find_if(models.begin(), models.end(), [&](const ModelResult& m) { return m.order == Order(q, s); });
  if (inner == models.end()) return nullptr;
  const double margin = std::max(kGrowthMarginNats, 3.0 * std::hypot(chosen.run.log_z_error, inner->run.log_z_error));
  return chosen.run.log_z > inner->run.log_z + margin ? &*inner : nullptr;
}

}  // namespace

std::optional<GridStep> next_grid_step(const std::vector<ModelResult>& models, std::size_t selected, int qmax,
                                       int smax, const FitSettings& settings, int real_data_values,
                                       double spent_calls, double budget_calls, std::string& refusal) {
  refusal.clear();
  const ModelResult& best = models.at(selected);
  const Order chosen = best.order;
  const ModelResult* q_inner = chosen.q() == qmax ? rising_from(models, best, 'Q') : nullptr;
  const ModelResult* s_inner = chosen.s() == smax ? rising_from(models, best, 'S') : nullptr;
  const bool q_edge = q_inner != nullptr, s_edge = s_inner != nullptr;
  if (!q_edge && !s_edge) return std::nullopt;
  const std::string edge = q_edge && s_edge ? fmt::format("the corner Q = {}, S = {}", qmax, smax)
                           : q_edge         ? fmt::format("the edge Q = {}", qmax)
                                            : fmt::format("the edge S = {}", smax);
  const int q_cap = settings.qmax + settings.grid_growth, s_cap = settings.smax + settings.grid_growth;
  const bool grow_q = q_edge && qmax < q_cap && qmax < Order::kMaxPoles;
  const bool grow_s = s_edge && smax < s_cap && smax < Order::kMaxPoles;
  if (!grow_q && !grow_s) {
    refusal = fmt::format("{} lies on {} of the grid and the grid may not grow further ({} = {}); larger orders "
                          "were not tried",
                          chosen.name(), edge, setting("grid_growth"), settings.grid_growth);
    return std::nullopt;
  }
  GridStep step;
  step.qmax = qmax + (grow_q ? 1 : 0);
  step.smax = smax + (grow_s ? 1 : 0);
  for (const Order& o : order_grid(step.qmax, step.smax))
    if (o.q() > qmax || o.s() > smax) step.add.push_back(o);
  const Order largest(step.qmax, step.smax);
  if (largest.dim() + 2 > real_data_values) {
    refusal = fmt::format("{} lies on {} of the grid; growing it to {} would need more than the K = {} real data "
                          "values; larger orders were not tried",
                          chosen.name(), edge, largest.name(), real_data_values);
    return std::nullopt;
  }
  for (const Order& o : step.add) step.calls += estimated_calls(models, o);
  if (spent_calls + step.calls > budget_calls) {
    refusal = fmt::format("{} lies on {} of the grid; growing it to Q0-{} x S0-{} would cost about {:.3g} M likelihood "
                          "calls, beyond the budget ({:.3g} M left of the first round's {:.3g} M); larger orders were "
                          "not tried (raise {}/{} to include them)",
                          chosen.name(), edge, step.qmax, step.smax, 1e-6 * step.calls,
                          1e-6 * std::max(0.0, budget_calls - spent_calls), 1e-6 * budget_calls, setting("qmax"),
                          setting("smax"));
    return std::nullopt;
  }
  const auto range = [](char kind, int max) {
    return max == 0 ? fmt::format("{} = 0", kind) : fmt::format("{}0-{}", kind, max);
  };
  std::string added;
  if (grow_q) added = fmt::format("Q = {} for {}", step.qmax, range('S', step.smax));
  if (grow_s) added += fmt::format("{}S = {} for {}", added.empty() ? "" : " and ", step.smax, range('Q', step.qmax));
  std::string gains;
  for (const ModelResult* inner : {q_inner, s_inner})
    if (inner != nullptr)
      gains += fmt::format("{}{:.1f} dB over {}", gains.empty() ? "" : ", ", deciban(best.run.log_z, inner->run.log_z),
                           inner->order.name());
  step.reason = fmt::format("{} lies on {} of the grid ({}): added {}", chosen.name(), edge, gains, added);
  return step;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "selection/accuracy_stop.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "selection/missed_modes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace admitgen {

void estimate_passive(const Measurement& data, const FitSettings& settings, std::vector<ModelResult>& models,
                      const passivity::LazyPassiveBound& bound) {
  std::vector<std::size_t> orders;
  for (std::size_t i = 0; i < models.size(); ++i)
    if (!models[i].accuracy) orders.push_back(i);
  // Largest first, so the longest tasks start first.
  std::stable_sort(orders.begin(), orders.end(),
                   [&](auto a, auto b) { return models[a].order.dim() > models[b].order.dim(); });
  run_in_parallel(orders, settings.threads, [&](std::size_t i) {
    auto& m = models[i];
    m.passive = passivity::passive_estimate(data, m.order, best_samples(m, passivity::PassiveEstimate::kCandidates),
                                            settings.data_count, passivity::PassiveEstimate::kStarts, &bound,
                                            settings.priors.admittance_scale);
    m.accuracy = order_accuracy(data, m.order, m.passive.theta, settings.target);
  });
}

std::size_t select_usable(const FitSettings& settings, const std::vector<ModelResult>& models) {
  std::vector<double> log_z, error;
  std::vector<int> buffers;
  std::vector<bool> meets, within, usable;
  for (const auto& m : models) {
    log_z.push_back(m.run.log_z);
    error.push_back(m.run.log_z_error);
    buffers.push_back(m.order.buffers());
    meets.push_back(m.accuracy && m.accuracy->meets);
    within.push_back(settings.max_buffers <= 0 || m.order.buffers() <= settings.max_buffers);
    usable.push_back(within.back() && !runs_disagree(m));
  }
  const bool any = std::find(usable.begin(), usable.end(), true) != usable.end();
  return settings.rule.select(log_z, error, buffers, meets, any ? usable : within);
}

std::string target_met_note(const Measurement& data, const FitSettings& settings, const std::vector<ModelResult>& models,
                            std::size_t selected, bool would_grow) {
  const ModelResult& sel = models[selected];
  if (!sel.accuracy) return {};
  if (!sel.accuracy->meets)
    return would_grow ? fmt::format("the data support more poles (ln Z still rises towards the orders beyond {}), "
                                    "which were not fitted: more poles cannot meet the target (see its warning)",
                                    sel.order.name())
                      : std::string{};
  std::size_t top = selected;
  for (std::size_t i = 0; i < models.size(); ++i)
    if (!runs_disagree(models[i]) && models[i].run.log_z > models[top].run.log_z) top = i;
  const std::string met = fmt::format("{} already meets {}", sel.order.name(), settings.target.describe());
  if (top != selected) {
    const ModelResult& t = models[top];
    return fmt::format(
        "the data support more poles (+{:.1f} nats at {}); {}; {} more buffers per node would change α by at most "
        "{:.3f}", t.run.log_z - sel.run.log_z, t.order.name(), met, t.order.buffers() - sel.order.buffers(),
        band_alpha_change(data, sel.order, sel.passive.theta, t.order, t.passive.theta));
  }
  if (!would_grow) return {};
  return fmt::format("the data support more poles (ln Z still rises towards the orders beyond {}, not fitted); {}",
                     sel.order.name(), met);
}

namespace {

/// A peak of the residual at most this many points wide is narrower than any pole pair the data can resolve: an
/// artefact of the measurement more likely than a feature of the material.
constexpr int kSpikePoints = 3;
bool is_spike(const OrderAccuracy& a) { return a.peak_points <= kSpikePoints; }

/// "a spike at 893.75 Hz 1 point(s) wide that no smooth model follows (…)".
std::string spike(const OrderAccuracy& a) {
  return fmt::format("a spike at {:.6g} Hz {} point(s) wide that no smooth model follows (a measurement artefact, or "
                     "a resonance narrower than the frequency step)", a.peak_hz, a.peak_points);
}

}  // namespace

std::string target_out_of_reach(const Measurement& data, const FitSettings& settings, const ModelResult& selected,
                                const passivity::LazyPassiveBound& bound) {
  if (settings.target.max_band_delta_alpha <= 0.0 || !selected.accuracy || selected.accuracy->meets) return {};
  const OrderAccuracy& a = *selected.accuracy;
  const passivity::PassiveEstimate& p = selected.passive;
  // A residual without correlation along frequency is the measurement's noise: no order follows it.
  constexpr double kNoiseLag1 = 0.5;
  if (a.residual_lag1 < kNoiseLag1)
    return fmt::format("the residual there is noise (its lag-1 autocorrelation over frequency is {:.2f}), which "
                       "alone moves α by that much at single points; no order can meet a target below the data's "
                       "noise: relax {}", a.residual_lag1, setting("target.max_band_delta_alpha"));
  // Passivity, not the order, limits what ships: the passive estimate costs more than kCostRatio over the best
  // sample, and the closest passive admittance of any order (the passive bound, a dense dictionary of passive
  // terms: docs/passivity.md, "The passive bound") misses the target too.
  if (p.relative_rms_residual > passivity::PassiveEstimate::kCostRatio * p.best_sample_relative_rms_residual) {
    const OrderAccuracy b = curve_accuracy(data, bound.get().fitted, settings.target);
    if (!b.meets)
      return fmt::format("passivity, not the order, limits what ships: the passive estimate fits at {:.3g} relative "
                         "RMS against the best sample's {:.3g}, and the closest passive admittance of any order (the "
                         "passive bound) misses the target too, at |Δα| = {:.3f} in the {:.0f} Hz band ({:.3g} "
                         "relative RMS), so more poles cannot meet it; `admitgen diagnose` with the data alone names "
                         "the measurement-chain effect, if any", p.relative_rms_residual,
                         p.best_sample_relative_rms_residual, b.max_band_delta_alpha, b.worst_band_hz, b.relative_rms);
  }
  // Out of reach when the order meets the target beside a spike.
  if (is_spike(a) && a.max_band_delta_alpha_beside_peak <= settings.target.max_band_delta_alpha)
    return fmt::format("the data hold {}, and beside it {} meets the target (|Δα| ≤ {:.3f}): check the data there, or "
                       "leave it out ({})", spike(a), selected.order.name(), a.max_band_delta_alpha_beside_peak,
                       setting("band"));
  return {};
}

std::string target_missed_warning(const Measurement& data, const FitSettings& settings,
                                  const std::vector<ModelResult>& models, std::size_t selected,
                                  const passivity::LazyPassiveBound& bound) {
  for (const auto& m : models)
    if (m.accuracy && m.accuracy->meets && (settings.max_buffers <= 0 || m.order.buffers() <= settings.max_buffers))
      return {};
  const ModelResult& sel = models[selected];
  if (!sel.accuracy) return {};
  const OrderAccuracy& a = *sel.accuracy;
  const std::string missed = fmt::format(
      "no fitted order meets the accuracy target ({}): the selected {} misses it most in the {:.0f} Hz band (|Δα| = "
      "{:.3f}, relative RMS {:.3g})", settings.target.describe(), sel.order.name(), a.worst_band_hz,
      a.max_band_delta_alpha, a.relative_rms);
  if (const std::string why = target_out_of_reach(data, settings, sel, bound); !why.empty()) return missed + ": " + why;
  if (is_spike(a))
    return fmt::format("{}, where the data hold {}, and beside it |Δα| reaches {:.3f}: check the data there, or leave "
                       "it out ({})", missed, spike(a), a.max_band_delta_alpha_beside_peak, setting("band"));
  return fmt::format("{}, where the data hold a feature at {:.6g} Hz about {:.3g} Hz wide that the model does not "
                     "follow (it needs a pole pair of its own: allow larger orders, {} or {}, or relax {})",
                     missed, a.peak_hz, a.peak_width_hz, setting("max_buffers"), setting("grid_growth"),
                     setting("target.max_band_delta_alpha"));
}

}  // namespace admitgen

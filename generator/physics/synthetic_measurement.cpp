// SPDX-License-Identifier: MIT
#include "physics/synthetic_measurement.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "physics/noise.hpp"
#include "physics/overloaded.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <set>

namespace admitgen {
namespace {

template <class T>
const T* find_effect(const std::vector<Effect>& effects) {
  for (const auto& e : effects)
    if (const T* found = std::get_if<T>(&e)) return found;
  return nullptr;
}

/// Step 1: the material with the air gaps behind it.
Material with_air_gap(const SynthesisRequest& r) {
  Material m = r.material;
  if (const auto* gap = find_effect<AirGap>(r.effects)) std::get<LayeredAbsorber>(m).layers.push_back(AirLayer{gap->gap_m});
  return m;
}

/// Step 3: sample effects in the order given.
Eigen::ArrayXcd apply_sample_effects(const SynthesisRequest& r, const Air& air, Eigen::ArrayXcd y) {
  for (const auto& effect : r.effects)
    std::visit(Overloaded{[&](const EdgeGap& e) {
                            y = apply_edge_gap(e, *r.tube.diameter_m, air, r.f_hz, y);
                          },
                          [&](const FrameResonance& e) { y = apply_frame_resonance(e, r.f_hz, y); },
                          [&](const FractionalOrder& e) { y = apply_fractional_order(e, r.f_hz, y); },
                          [](const auto&) {}},
               effect);
  return y;
}

/// Step 4: the chain deviation the effects describe, and whether anything beyond a reference-plane
/// shift needs the full chain.
struct ChainPlan {
  ChainDeviation deviation;
  bool needs_chain = false;
};

ChainPlan chain_plan(const std::vector<Effect>& effects) {
  ChainPlan plan;
  for (const auto& effect : effects)
    std::visit(Overloaded{[&](const ReferencePlane& e) { plan.deviation.reference_plane_m = e.delta_m; },
                          [&](const MicSpacing& e) {
                            plan.deviation.spacing_error_m = e.delta_m;
                            plan.needs_chain = true;
                          },
                          [&](const MicMismatch& e) {
                            plan.deviation.mic_ratio = (1.0 + e.gain) * std::polar(1.0, e.phase_deg * static_cast<double>(EIGEN_PI) / 180.0);
                            plan.needs_chain = true;
                          },
                          [&](const TemperatureOffset& e) {
                            plan.deviation.temperature_offset_k = e.delta_k;
                            plan.needs_chain = true;
                          },
                          [&](const TubeLosses&) {
                            plan.deviation.tube_losses = true;
                            plan.needs_chain = true;
                          },
                          [](const auto&) {}},
               effect);
  return plan;
}

}  // namespace

TubeGeometry TubeSetup::geometry(const std::string& why) const {
  std::vector<std::string> missing;
  if (!diameter_m) missing.push_back(setting("tube.diameter_m"));
  if (!spacing_m) missing.push_back(setting("tube.spacing_m"));
  if (!mic1_distance_m) missing.push_back(setting("tube.mic1_distance_m"));
  if (!missing.empty())
    throw InputError(fmt::format("{} needs the tube geometry {}, {} and {} (metres); missing: {}", why,
                                 setting("tube.diameter_m"), setting("tube.spacing_m"),
                                 setting("tube.mic1_distance_m"), fmt::join(missing, ", ")));
  return TubeGeometry(*diameter_m, *spacing_m, *mic1_distance_m);
}

Eigen::ArrayXd log_spaced_frequencies(double lo_hz, double hi_hz, int n) {
  if (!(lo_hz > 0.0 && hi_hz > lo_hz && std::isfinite(hi_hz)))
    throw InputError(fmt::format("frequency band {}:{} Hz: need 0 < FMIN < FMAX", lo_hz, hi_hz));
  if (n < 2) throw InputError(fmt::format("{} {}: need at least 2 frequencies", setting("points"), n));
  Eigen::ArrayXd f(n);
  for (int i = 0; i < n; ++i) f[i] = lo_hz * std::pow(hi_hz / lo_hz, static_cast<double>(i) / (n - 1));
  f[n - 1] = hi_hz;
  return f;
}

void validate(const SynthesisRequest& r) {
  ADMITGEN_ENSURE(r.f_hz.size() > 0 && (r.f_hz > 0.0).all(), "synthesis needs positive frequencies");
  if (!(std::isfinite(r.noise_std) && r.noise_std >= 0.0))
    throw InputError(fmt::format("{} {}: the noise std must be >= 0", setting("noise_std"), r.noise_std));
  std::set<std::string> seen;
  for (const auto& effect : r.effects) {
    const std::string name = effect_name(effect);
    if (!seen.insert(name).second) throw InputError(fmt::format("effect '{}' given twice; give it once", name));
    const std::string why = fmt::format("effect '{}'", name);
    switch (geometry_need(effect)) {
      case GeometryNeed::full: (void)r.tube.geometry(why); break;
      case GeometryNeed::diameter:
        if (!r.tube.diameter_m) throw InputError(fmt::format("{} needs {} (metres)", why, setting("tube.diameter_m")));
        break;
      case GeometryNeed::none: break;
    }
    if (std::holds_alternative<AirGap>(effect) && !std::holds_alternative<LayeredAbsorber>(r.material))
      throw InputError("effect 'air_gap' needs a layered material SPEC (an air layer is inserted before the rigid "
                       "backing); a multipole surface has no layers");
    if (std::holds_alternative<HeteroscedasticNoise>(effect) && !(r.noise_std > 0.0))
      throw InputError("effect 'heteroscedastic_noise' shapes the noise: give " + setting("noise_std") + " STD > 0");
  }
}

Synthesis synthesize(const SynthesisRequest& r) {
  validate(r);
  Synthesis out;
  const Air air = Air::at_celsius(r.tube.temperature_c);
  Eigen::ArrayXcd y = surface_admittance(with_air_gap(r), air, r.f_hz);
  y = apply_sample_effects(r, air, y);

  const ChainPlan plan = chain_plan(r.effects);
  if (plan.needs_chain) {
    const TubeGeometry tube = r.tube.geometry("the measurement-chain effects");
    const FrequencyRange range = working_range(air, tube);
    if (r.f_hz[0] < range.lo_hz || r.f_hz[r.f_hz.size() - 1] > range.hi_hz)
      out.warnings.push_back(fmt::format("band {:.6g}-{:.6g} Hz leaves the ISO 10534-2 working range {:.6g}-{:.6g} Hz "
                                         "of this tube; the chain effects are amplified there",
                                         r.f_hz[0], r.f_hz[r.f_hz.size() - 1], range.lo_hz, range.hi_hz));
    y = measure_through_chain(y, r.f_hz, air, tube, plan.deviation);
  } else if (plan.deviation.reference_plane_m != 0.0) {
    y = apply_reference_plane(ReferencePlane{plan.deviation.reference_plane_m}, air, r.f_hz, y);
  }

  if (r.noise_std > 0.0) {
    Eigen::ArrayXd std = Eigen::ArrayXd::Constant(r.f_hz.size(), r.noise_std);
    if (const auto* h = find_effect<HeteroscedasticNoise>(r.effects))
      std = heteroscedastic_std(r.noise_std, h->scale, air, *r.tube.spacing_m, r.f_hz);
    Rng rng(r.seed);
    y += complex_gaussian_noise(std, rng);
  }
  out.y = y;
  return out;
}

}  // namespace admitgen

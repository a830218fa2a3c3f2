// SPDX-License-Identifier: MIT
#include "diagnosis/effect_candidates.hpp"

#include "physics/effects.hpp"
#include "physics/noise.hpp"
#include "physics/two_microphone.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>

namespace admitgen::diagnosis {
namespace {

constexpr double kMm = 1e-3;

using Shape = ParameterPrior::Shape;

/// Everything an effect model reads, shared by the candidates (held by shared_ptr in their closures).
struct Context {
  Eigen::ArrayXd f;
  Eigen::ArrayXcd y_sim;
  Air air;
  TubeSetup tube;
  SimulatedSide sim;
  std::optional<TwoMicrophoneChain> chain;  ///< y_sim through the tube (full geometry only)
  SlitModel slit;                           ///< the edge gap's slit on this grid
};
using ContextPtr = std::shared_ptr<const Context>;

EffectPrediction plain(Eigen::ArrayXcd y) { return {std::move(y), {}}; }

/// A chain effect: the true chain deviates from the processed one (two_microphone.hpp).
EffectCandidate chain_effect(std::string name, std::vector<ParameterPrior> priors, const ContextPtr& c,
                             std::function<ChainDeviation(const double*)> deviation) {
  return {std::move(name), std::move(priors), {},
          [c, deviation](const double* t) { return plain(c->chain->measure(deviation(t))); }};
}

bool full_geometry(const TubeSetup& t) { return t.diameter_m && t.spacing_m && t.mic1_distance_m; }

/// Whether the two-microphone inversion is regular at every frequency (sin ks ≠ 0).
bool regular_transfer(const Context& c) {
  const Eigen::ArrayXd sin_ks = (2.0 * EIGEN_PI * c.f * *c.tube.spacing_m / c.air.c0).sin().abs();
  return (sin_ks > 1e-6).all();
}

void add_chain_effects(std::vector<EffectCandidate>& out, const ContextPtr& c) {
  out.push_back(chain_effect("mic_spacing", {{"delta_m", Shape::uniform, -3 * kMm, 3 * kMm}}, c,
                             [](const double* t) {
                               ChainDeviation d;
                               d.spacing_error_m = t[0];
                               return d;
                             }));
  out.push_back(chain_effect("mic_mismatch", {{"gain", Shape::uniform, -0.1, 0.1}, {"phase_deg", Shape::uniform, -5, 5}},
                             c, [](const double* t) {
                               ChainDeviation d;
                               d.mic_ratio = (1.0 + t[0]) * std::polar(1.0, t[1] * static_cast<double>(EIGEN_PI) / 180.0);
                               return d;
                             }));
  out.push_back(chain_effect("temperature", {{"delta_k", Shape::uniform, -10, 10}}, c, [](const double* t) {
    ChainDeviation d;
    d.temperature_offset_k = t[0];
    return d;
  }));
  out.push_back(chain_effect("tube_losses", {}, c, [](const double*) {
    ChainDeviation d;
    d.tube_losses = true;
    return d;
  }));
}

EffectCandidate heteroscedastic_noise(const ContextPtr& c) {
  return {"heteroscedastic_noise", {{"scale", Shape::uniform, 0.0, 0.5}}, {}, [c](const double* t) {
            return EffectPrediction{c->y_sim, heteroscedastic_std(1.0, t[0], c->air, *c->tube.spacing_m, c->f)};
          }};
}

EffectCandidate edge_gap(const ContextPtr& c) {
  return {"edge_gap",
          {{"width_m", Shape::log_uniform, 0.05 * kMm, 3 * kMm}, {"depth_m", Shape::log_uniform, 5 * kMm, 200 * kMm}},
          {},
          [c](const double* t) {
            return plain(c->slit.edge_gap(EdgeGap{t[0], t[1]}, *c->tube.diameter_m, c->y_sim));
          }};
}

EffectCandidate frame_resonance(const ContextPtr& c) {
  const double f_min = c->f[0], f_max = c->f[c->f.size() - 1];
  return {"frame_resonance",
          {{"f0_hz", Shape::log_uniform, f_min, f_max}, {"q", Shape::log_uniform, 1, 100},
           {"y_peak", Shape::log_uniform, 1e-3, 3}},
          {},
          [c](const double* t) { return plain(apply_frame_resonance(FrameResonance{t[0], t[1], t[2]}, c->f, c->y_sim)); }};
}

EffectCandidate fractional_order(const ContextPtr& c) {
  const double f_ref = std::sqrt(c->f[0] * c->f[c->f.size() - 1]);
  return {"fractional_order",
          {{"c_plus", Shape::uniform, 0.0, 0.5}, {"c_minus", Shape::uniform, 0.0, 0.5}},
          {{"f_ref_hz", f_ref}},
          [c, f_ref](const double* t) {
            return plain(apply_fractional_order(FractionalOrder{t[0], t[1], f_ref}, c->f, c->y_sim));
          }};
}

EffectCandidate air_gap(const ContextPtr& c) {
  return {"air_gap", {{"gap_m", Shape::log_uniform, 0.1 * kMm, 30 * kMm}}, {}, [c](const double* t) {
            auto layered = std::get<LayeredAbsorber>(*c->sim.material());
            layered.layers.push_back(AirLayer{t[0]});
            return plain(surface_admittance(Material{layered}, c->air, c->f));
          }};
}

/// The prior of ratio is log-uniform on [0.8, 1.25], narrowed to where the simulated side is known
/// (a table covers only its own band); std::nullopt when that leaves less than ±2 % around 1.
std::optional<ParameterPrior> frequency_scale_prior(const Context& c) {
  const double f_min = c.f[0], f_max = c.f[c.f.size() - 1];
  double lo = 0.8, hi = 1.25;
  while (lo < 0.98 && !c.sim.covers(f_min * lo)) lo += 0.005;
  while (hi > 1.02 && !c.sim.covers(f_max * hi)) hi -= 0.005;
  if (!(c.sim.covers(f_min * lo) && c.sim.covers(f_max * hi)) || lo > 0.98 || hi < 1.02) return std::nullopt;
  return ParameterPrior{"ratio", Shape::log_uniform, lo, hi};
}

EffectCandidate frequency_scale(const ContextPtr& c, const ParameterPrior& prior) {
  return {"frequency_scale", {prior}, {}, [c](const double* t) { return plain(c->sim.admittance(c->f * t[0])); }};
}

}  // namespace

double ParameterPrior::transform(double u) const {
  return shape == Shape::uniform ? lo + u * (hi - lo) : lo * std::pow(hi / lo, u);
}

std::string ParameterPrior::describe() const {
  return fmt::format("{} [{:g}, {:g}]", shape == Shape::uniform ? "uniform" : "log-uniform", lo, hi);
}

std::vector<EffectCandidate> effect_candidates(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_sim,
                                               const SimulatedSide& sim, const TubeSetup& tube) {
  const Air air = Air::at_celsius(tube.temperature_c);
  std::optional<TwoMicrophoneChain> chain;
  if (full_geometry(tube)) chain.emplace(y_sim, f_hz, air, tube.geometry("the chain effects"));
  const auto c = std::make_shared<const Context>(Context{f_hz, y_sim, air, tube, sim, std::move(chain), SlitModel(air, f_hz)});
  std::vector<EffectCandidate> out;
  out.push_back({"reference_plane", {{"delta_m", Shape::uniform, -10 * kMm, 10 * kMm}}, {}, [c](const double* t) {
                   return plain(apply_reference_plane(ReferencePlane{t[0]}, c->air, c->f, c->y_sim));
                 }});
  if (full_geometry(tube)) add_chain_effects(out, c);
  if (tube.diameter_m) out.push_back(edge_gap(c));
  out.push_back(frame_resonance(c));
  out.push_back(fractional_order(c));
  if (sim.material() && std::holds_alternative<LayeredAbsorber>(*sim.material())) out.push_back(air_gap(c));
  if (full_geometry(tube) && regular_transfer(*c)) out.push_back(heteroscedastic_noise(c));
  if (const auto prior = frequency_scale_prior(*c)) out.push_back(frequency_scale(c, *prior));
  return out;
}

}  // namespace admitgen::diagnosis

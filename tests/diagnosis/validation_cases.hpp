// SPDX-License-Identifier: MIT
/// @file
/// The generated cases of the diagnosis validation suite: a base material, an effect at a size, the
/// tube, realistic noise; `run_case` synthesises the "real" data with physics/synthetic_measurement
/// (what `admitgen synth` does) and diagnoses it against the clean base material SPEC, without telling
/// `diagnose` the effect.
///
/// Setup (docs/physics.md §5.0 reference tube): d = 100 mm, s = 50 mm, x1 = 100 mm, 20 °C; 120 log-spaced
/// points 100-2000 Hz (14 one-third-octave bands); complex noise σ = 0.003 on y (E|n|² = σ²), about
/// the random error of a tube measurement with coherence γ² ≈ 0.99 in mid band (docs/physics.md §5.1 l).
/// 60 live points per effect: effects have 0-3 parameters, the evidence error √(H/n) ≈ 0.5 nat (2 dB)
/// is small next to the 20 dB decision threshold, and one case takes about a second.
#pragma once

#include "core/rng.hpp"
#include "diagnosis/diagnosis.hpp"
#include "physics/material_spec.hpp"
#include "physics/noise.hpp"
#include "physics/synthetic_measurement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <complex>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace admitgen::test {

struct BaseMaterial {
  std::string name;
  std::string spec;
  double thickness_m;  ///< depth of the absorbing part (edge_gap slit depth)
};

inline const std::vector<BaseMaterial>& base_materials() {
  static const std::vector<BaseMaterial> m{
      {"porous", "miki(sigma=10000, d=50mm)", 0.05},
      {"layered", "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)",
       0.03},
      {"mpp", "mpp(hole=0.4mm, t=0.4mm, p=1%) + air(d=50mm)", 0.05}};
  return m;
}

/// A change of the "real" data that no vocabulary effect describes (applied before the noise).
using Distortion = std::function<Eigen::ArrayXcd(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y)>;

struct ValidationCase {
  std::string label;        ///< e.g. "porous frame_resonance clear"
  std::string truth;        ///< the effect's documented name, "none", or "unexplained" (out of vocabulary)
  std::string effect;       ///< synth --effect text ("" for a control)
  std::string second;       ///< a second effect (two-effect cases), its documented name in truth_second
  std::string truth_second;
  std::string third;        ///< a third effect (three-effect cases), its documented name in truth_third
  std::string truth_third;
  std::string fourth;       ///< a fourth effect (four-effect cases), its documented name in truth_fourth
  std::string truth_fourth;
  /// The "real" data composed by another route than the one diagnose composes its candidates by
  /// (other_route_y: the sample effects in the reverse order, the chain from the pressure field;
  /// docs/diagnosis.md, "Four effects and mimics beside their partners").
  bool other_route = false;
  std::string real_spec;    ///< the real sample's SPEC when it differs from the simulated one ("" = the same)
  std::string parameter;    ///< catalogue-parameter cases: the SPEC parameter that is off ("1.sigma")
  double ratio = 1.0;       ///< and by how much
  Distortion distort;       ///< out-of-vocabulary change of the real data
  bool sim_table = false;   ///< the simulated side as a CSV-like table (no layers known to diagnose)
  BaseMaterial material;
  double tube_diameter_m = 0.1;
  double mic_distance_m = 0.1;
  std::uint64_t seed = 1;
  double signature_hz = 0.0;  ///< a frequency the worst band must contain (0 = no signature)
  bool clear = false;
};

inline constexpr double kNoise = 0.003;

inline TubeSetup case_tube(const ValidationCase& c) { return {c.tube_diameter_m, 0.05, c.mic_distance_m, 20.0}; }

/// What the "real" data of a case are made of, without the noise when `noise` is false (the exact model).
inline SynthesisRequest truth_request(const ValidationCase& c, bool noise) {
  SynthesisRequest request{parse_material_spec(c.real_spec.empty() ? c.material.spec : c.real_spec), {},
                           log_spaced_frequencies(100.0, 2000.0, 120), noise ? kNoise : 0.0, c.seed, case_tube(c)};
  for (const auto& text : {c.effect, c.second, c.third, c.fourth})
    if (!text.empty() && (noise || effect_name(parse_effect(text)) != "heteroscedastic_noise"))
      request.effects.push_back(parse_effect(text));  // heteroscedastic_noise shapes the noise only
  return request;
}

/// The chain of an other_route case, written out from the pressure field in the tube instead of through
/// physics/two_microphone (and in another order: the microphones placed first, then the air, the losses
/// and the mismatch): x from the true sample face, p(x) = e^{jk_t x} + R_t e^{−jk_t x} with k_t the true
/// wavenumber (air at T + ΔT; with tube losses k_t = ω/c + (1 − j)·0.0194·√f/(c·d), docs/cli.md) and
/// R_t = (1 − y_t)/(1 + y_t), y_t = y·ρ0c0(T + ΔT)/ρ0c0(T); the far microphone at x1 + δ_ref, the near one
/// at x1 + δ_ref − s − δ_s, its pressure scaled by (1 + gain)·e^{jφ}; processed as ISO 10534-2 with the
/// nominal x1, s and k = ω/c(T): R = (H12 − e^{−jks})/(e^{jks} − H12)·e^{2jkx1}, y = (1 − R)/(1 + R).
/// The same physics as the one chain of the search (docs/physics.md §5), by another computation.
inline Eigen::ArrayXcd chain_by_pressure_field(const Eigen::ArrayXcd& y, const Eigen::ArrayXd& f_hz, const TubeSetup& tube,
                                               const std::vector<Effect>& chain) {
  double ref = 0.0, spacing = 0.0, dk = 0.0;
  bool losses = false;
  std::complex<double> mismatch{1.0, 0.0};
  for (const auto& e : chain) {
    if (const auto* p = std::get_if<ReferencePlane>(&e)) ref = p->delta_m;
    if (const auto* p = std::get_if<MicSpacing>(&e)) spacing = p->delta_m;
    if (const auto* p = std::get_if<TemperatureOffset>(&e)) dk = p->delta_k;
    if (std::holds_alternative<TubeLosses>(e)) losses = true;
    if (const auto* p = std::get_if<MicMismatch>(&e))
      mismatch = (1.0 + p->gain) * std::polar(1.0, p->phase_deg * static_cast<double>(EIGEN_PI) / 180.0);
  }
  const double x_far = *tube.mic1_distance_m + ref, x_near = x_far - *tube.spacing_m - spacing;
  const Air nominal = Air::at_celsius(tube.temperature_c), air = Air::at_celsius(tube.temperature_c + dk);
  const std::complex<double> j{0.0, 1.0};
  Eigen::ArrayXcd out(y.size());
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    const double omega = 2.0 * static_cast<double>(EIGEN_PI) * f_hz[i];
    std::complex<double> kt = omega / air.c0;
    if (losses) kt += (1.0 - j) * 0.0194 * std::sqrt(f_hz[i]) / (air.c0 * *tube.diameter_m);
    const std::complex<double> yt = y[i] * (air.rho0 * air.c0) / (nominal.rho0 * nominal.c0);
    const std::complex<double> rt = (1.0 - yt) / (1.0 + yt);
    const auto p = [&](double x) { return std::exp(j * kt * x) + rt * std::exp(-j * kt * x); };
    const std::complex<double> h12 = mismatch * p(x_near) / p(x_far);
    const double k = omega / nominal.c0, s = *tube.spacing_m, x1 = *tube.mic1_distance_m;
    const std::complex<double> r = (h12 - std::exp(-j * k * s)) / (std::exp(j * k * s) - h12) * std::exp(2.0 * j * k * x1);
    out[i] = (1.0 - r) / (1.0 + r);
  }
  return out;
}

/// The clean "real" data of an other_route case, composed by another route than synthesize (and the
/// search's combine_effects): the layered material with its air gap as a layer; the sample effects in the
/// reverse order (fractional_order, frame_resonance, edge_gap: the slit's area share then also scales the
/// resonance and the fractional terms, as if they acted on the sample alone, which the search's order
/// represents with y_peak, c₊ and c₋ smaller by that share); the chain by chain_by_pressure_field.
inline Eigen::ArrayXcd other_route_y(const SynthesisRequest& r) {
  validate(r);
  const Air air = Air::at_celsius(r.tube.temperature_c);
  Material m = r.material;
  std::vector<Effect> sample, chain;
  for (const auto& e : r.effects) {
    if (const auto* gap = std::get_if<AirGap>(&e)) std::get<LayeredAbsorber>(m).layers.push_back(AirLayer{gap->gap_m});
    else if (std::holds_alternative<EdgeGap>(e) || std::holds_alternative<FrameResonance>(e) ||
             std::holds_alternative<FractionalOrder>(e))
      sample.push_back(e);
    else if (!std::holds_alternative<HeteroscedasticNoise>(e) && !std::holds_alternative<NoEffect>(e))
      chain.push_back(e);
  }
  std::sort(sample.begin(), sample.end(), [](const Effect& a, const Effect& b) { return a.index() > b.index(); });
  Eigen::ArrayXcd y = surface_admittance(m, air, r.f_hz);
  for (const auto& e : sample) {
    if (const auto* g = std::get_if<EdgeGap>(&e)) y = apply_edge_gap(*g, *r.tube.diameter_m, air, r.f_hz, y);
    if (const auto* f = std::get_if<FrameResonance>(&e)) y = apply_frame_resonance(*f, r.f_hz, y);
    if (const auto* f = std::get_if<FractionalOrder>(&e)) y = apply_fractional_order(*f, r.f_hz, y);
  }
  return chain.empty() ? y : chain_by_pressure_field(y, r.f_hz, r.tube, chain);
}

/// The noise of a case's real data (heteroscedastic when the case holds heteroscedastic_noise), as
/// synthesize draws it.
inline Eigen::ArrayXd case_noise_std(const SynthesisRequest& r) {
  for (const auto& e : r.effects)
    if (const auto* h = std::get_if<HeteroscedasticNoise>(&e))
      return heteroscedastic_std(kNoise, h->scale, Air::at_celsius(r.tube.temperature_c), *r.tube.spacing_m, r.f_hz);
  return Eigen::ArrayXd::Constant(r.f_hz.size(), kNoise);
}

/// The real data without noise: the truth exactly (what an exact model of the case would predict).
inline Eigen::ArrayXcd exact_y(const ValidationCase& c) {
  const SynthesisRequest r = truth_request(c, false);
  const Eigen::ArrayXcd y = c.other_route ? other_route_y(r) : synthesize(r).y;
  return c.distort ? c.distort(r.f_hz, y) : y;
}

/// The request `run_case` diagnoses: the synthesised "real" data against the clean base material (a SPEC,
/// or its table on 400 points 50-2500 Hz when sim_table).
inline diagnosis::DiagnosisRequest case_request(const ValidationCase& c, int live = 60) {
  const TubeSetup tube = case_tube(c);
  const SynthesisRequest request = truth_request(c, true);
  Measurement real;
  real.path = c.label;
  real.f_hz = request.f_hz;
  if (c.distort || c.other_route) {  // noise on the clean data, as in synthesize
    Rng rng(c.seed);
    real.y = exact_y(c) + complex_gaussian_noise(case_noise_std(request), rng);
  } else {
    real.y = synthesize(request).y;
  }
  const Air air = Air::at_celsius(tube.temperature_c);
  const Material base = parse_material_spec(c.material.spec);
  diagnosis::SimulatedSide sim = diagnosis::SimulatedSide::from_material(base, air, c.material.spec);
  if (c.sim_table) {
    Measurement table;
    table.f_hz = log_spaced_frequencies(50.0, 2500.0, 400);
    table.y = surface_admittance(base, air, table.f_hz);
    sim = diagnosis::SimulatedSide::from_table(table, c.material.spec + " as a table");
  }
  diagnosis::DiagnosisRequest d{real, sim, tube, {}, std::nullopt};
  d.settings.sampler.live = live;
  d.settings.sampler.seed = c.seed;
  return d;
}

/// The effect of each case at a clear and at a marginal size (synth --effect text). Sizes are chosen
/// against σ = 0.003: "clear" leaves the effect's gap several times the noise, "marginal" near the
/// detection limit (docs/diagnosis.md table).
struct EffectSizes {
  std::string name;
  std::string clear;
  std::string marginal;
};

inline std::vector<EffectSizes> effect_sizes(const BaseMaterial& m, double f0) {
  const std::string depth = fmt::format("{}", m.thickness_m);
  return {{"reference_plane", "reference_plane:delta_m=3mm", "reference_plane:delta_m=0.5mm"},
          {"mic_spacing", "mic_spacing:delta_m=1mm", "mic_spacing:delta_m=0.2mm"},
          {"mic_mismatch", "mic_mismatch:gain=0.03,phase_deg=1", "mic_mismatch:gain=0.005,phase_deg=0.2"},
          {"temperature", "temperature:delta_k=8", "temperature:delta_k=2"},
          {"tube_losses", "tube_losses", "tube_losses"},
          {"edge_gap", "edge_gap:width_m=1mm,depth_m=" + depth, "edge_gap:width_m=0.3mm,depth_m=" + depth},
          {"frame_resonance", fmt::format("frame_resonance:f0_hz={},q=8,y_peak=0.1", f0),
           fmt::format("frame_resonance:f0_hz={},q=8,y_peak=0.02", f0)},
          {"fractional_order", "fractional_order:c_plus=0.05,c_minus=0.02,f_ref_hz=1000",
           "fractional_order:c_plus=0.01,c_minus=0.004,f_ref_hz=1000"},
          {"air_gap", "air_gap:gap_m=3mm", "air_gap:gap_m=0.5mm"},
          {"heteroscedastic_noise", "heteroscedastic_noise:scale=0.3", "heteroscedastic_noise:scale=0.1"}};
}

inline diagnosis::Diagnosis run_case(const ValidationCase& c, int live = 60) {
  return diagnosis::run_diagnosis(case_request(c, live));
}

}  // namespace admitgen::test

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
  for (const auto& text : {c.effect, c.second, c.third})
    if (!text.empty() && (noise || effect_name(parse_effect(text)) != "heteroscedastic_noise"))
      request.effects.push_back(parse_effect(text));  // heteroscedastic_noise shapes the noise only
  return request;
}

/// The real data without noise: the truth exactly (what an exact model of the case would predict).
inline Eigen::ArrayXcd exact_y(const ValidationCase& c) {
  const SynthesisRequest r = truth_request(c, false);
  const Eigen::ArrayXcd y = synthesize(r).y;
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
  if (c.distort) {  // the distortion acts on the clean data; the noise comes after it, as in synthesize
    Rng rng(c.seed);
    real.y = exact_y(c) + complex_gaussian_noise(Eigen::ArrayXd::Constant(request.f_hz.size(), kNoise), rng);
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

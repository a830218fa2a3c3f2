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

#include "diagnosis/diagnosis.hpp"
#include "physics/material_spec.hpp"
#include "physics/synthetic_measurement.hpp"

#include <cstdint>
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

struct ValidationCase {
  std::string label;        ///< e.g. "porous frame_resonance clear"
  std::string truth;        ///< the effect's documented name, or "none"
  std::string effect;       ///< synth --effect text ("" for a control)
  BaseMaterial material;
  double tube_diameter_m = 0.1;
  double mic_distance_m = 0.1;
  std::uint64_t seed = 1;
  double signature_hz = 0.0;  ///< a frequency the worst band must contain (0 = no signature)
  bool clear = false;
};

inline constexpr double kNoise = 0.003;

inline diagnosis::Diagnosis run_case(const ValidationCase& c, int live = 60) {
  TubeSetup tube{c.tube_diameter_m, 0.05, c.mic_distance_m, 20.0};
  SynthesisRequest request{parse_material_spec(c.material.spec), {}, log_spaced_frequencies(100.0, 2000.0, 120),
                           kNoise, c.seed, tube};
  if (!c.effect.empty()) request.effects.push_back(parse_effect(c.effect));
  Measurement real;
  real.path = c.label;
  real.f_hz = request.f_hz;
  real.y = synthesize(request).y;
  const Air air = Air::at_celsius(tube.temperature_c);
  diagnosis::DiagnosisRequest d{real,
                                diagnosis::SimulatedSide::from_material(request.material, air, c.material.spec),
                                tube,
                                {},
                                std::nullopt};
  d.sampler.live = live;
  d.sampler.seed = c.seed;
  return diagnosis::run_diagnosis(d);
}

}  // namespace admitgen::test

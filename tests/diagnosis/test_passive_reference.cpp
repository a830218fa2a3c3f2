// SPDX-License-Identifier: MIT
// `diagnose` with physics as the reference (diagnosis/passive_reference.hpp, docs/diagnosis.md "Physics as the
// reference"). The data are made by `synth`'s pipeline (physics/synthetic_measurement.hpp: the forward chain
// measure_through_chain, with its own noise), a route independent of the corrections the diagnosis inverts.
//  * correct_through_chain undoes measure_through_chain: both are closed forms in double, the ISO inversion
//    amplifying rounding by ≤ 1/|sin ks| ≈ 20 in this band, so 1e-10 relative is 10⁵ ε of margin and a wrong sign
//    or a missing ρc ratio (≥ 1e-3) fails it.
//  * Sweeps (fixed seeds; 5 materials × 4 effects and 5 passive controls, the size one run of the suite can
//    afford at a few seconds a diagnosis; ≥ 90 % of 20 is 18, of 5 controls all 5 (≥ 90 % of 5 rounds up)). Each effect is set where it breaks passivity well beyond
//    the noise (σ = 1e-3, under 1 % of |y|), as the other modes' "clear" sweeps do. reference_plane is negative:
//    δ > 0 is a lossless air layer in front of the wall, which is passive and causal, so passivity cannot see it
//    (docs/diagnosis.md, "Physics as the reference": +20 mm was answered `consistent` on 4 of these 5 walls).
#include "diagnosis/passive_reference.hpp"
#include "physics/effects.hpp"
#include "physics/material_spec.hpp"
#include "physics/synthetic_measurement.hpp"
#include "physics/two_microphone.hpp"

#include <doctest/doctest.h>

#include <fmt/core.h>

namespace admitgen::test {
namespace {

const TubeSetup kTube{0.1, 0.085, 0.235, 20.0};

Measurement synthetic(const std::string& spec, const std::vector<std::string>& effects, std::uint64_t seed) {
  SynthesisRequest r{parse_material_spec(spec), {}, log_spaced_frequencies(210.0, 1600.0, 80), 1e-3, seed, kTube};
  for (const auto& e : effects) r.effects.push_back(parse_effect(e));
  Measurement m;
  m.path = "synthetic";
  m.f_hz = r.f_hz;
  m.y = synthesize(r).y;
  return m;
}

// JCA layers (docs/materials.md 2.2): causal and passive by construction. Miki's law is not causal (its
// power laws break Kramers-Kronig), so its walls are not a passive-causal control.
const std::vector<std::string> kMaterials{
    "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=50mm)",
    "jca(phi=0.98, sigma=10000, alpha_inf=1.02, lambda=150um, lambda_th=300um, d=80mm)",
    "jca(phi=0.95, sigma=20000, alpha_inf=1.1, lambda=80um, lambda_th=160um, d=40mm) + air(d=30mm)",
    "jca(phi=0.99, sigma=8000, alpha_inf=1.01, lambda=200um, lambda_th=400um, d=100mm)",
    "jca(phi=0.9, sigma=60000, alpha_inf=1.2, lambda=40um, lambda_th=90um, d=30mm)"};

}  // namespace

TEST_CASE("passive reference: correct_through_chain undoes measure_through_chain") {
  const Eigen::ArrayXd f = log_spaced_frequencies(210.0, 1600.0, 50);
  const Air air = Air::at_celsius(20.0);
  const Eigen::ArrayXcd y = surface_admittance(parse_material_spec("miki(sigma=10000, d=50mm)"), air, f);
  const TubeGeometry g = kTube.geometry("test");
  ChainDeviation dev;
  dev.reference_plane_m = 0.01;
  dev.spacing_error_m = -0.002;
  dev.temperature_offset_k = 4.0;
  dev.tube_losses = true;
  dev.mic_ratio = std::polar(1.15, 0.05);
  const Eigen::ArrayXcd back = correct_through_chain(measure_through_chain(y, f, air, g, dev), f, air, g, dev);
  CHECK((back - y).abs().maxCoeff() / y.abs().maxCoeff() < 1e-10);
  // Undoing the wrong deviation does not give y back (the check above can fail).
  dev.temperature_offset_k = 0.0;
  const Eigen::ArrayXcd wrong = correct_through_chain(measure_through_chain(y, f, air, g, dev), f, air, g, ChainDeviation{});
  CHECK((wrong - y).abs().maxCoeff() / y.abs().maxCoeff() > 1e-3);
}

TEST_CASE("passive reference: the noise estimate recovers sigma of white noise on a smooth admittance") {
  // 80 points: the median of |d|² has a relative standard error of about 1.4/√n ≈ 0.16, σ's half that; 15 % on σ
  // is two standard errors.
  const Measurement m = synthetic(kMaterials[0], {}, 7);
  CHECK(std::sqrt(diagnosis::estimate_noise_variance(m.y)) == doctest::Approx(1e-3).epsilon(0.15));
}

// Twenty diagnoses of about 10 s each: in the suite "statistical", run by the optimised build, never under the
// sanitizers (tests/CMakeLists.txt). Seeds fixed (101-124).
TEST_SUITE("statistical") {

// The goal (docs/diagnosis.md "Physics as the reference") is 18 of 20: measured 18 of 20 since the grid is refined
// twice around its best cell (17 before: temperature was named mic_spacing once); the misses are reference_plane
// −20 mm answered tube_losses once and consistent once.
TEST_CASE("passive reference: one chain effect withheld is named (sweep)") {
  const std::vector<std::pair<std::string, std::string>> effects{
      {"reference_plane", "reference_plane:delta_m=-0.02"},
      {"mic_spacing", "mic_spacing:delta_m=0.003"},
      {"mic_mismatch", "mic_mismatch:gain=0.15,phase_deg=2"},
      {"temperature", "temperature:delta_k=8"}};
  int named = 0, runs = 0;
  std::uint64_t seed = 100;
  for (const auto& spec : kMaterials) {
    for (const auto& [name, text] : effects) {
      const auto d = diagnosis::diagnose_against_passivity(synthetic(spec, {text}, ++seed), kTube, 0);
      ++runs;
      if (d.verdict == name) ++named;
      else MESSAGE(fmt::format("{} + {}: {}", spec, text, d.verdict));
    }
    ++seed;  // the seeds of the controls below
  }
  MESSAGE(fmt::format("named {}/{}", named, runs));
  CHECK(runs == 20);
  CHECK(named >= 18);
}

TEST_CASE("passive reference: passive walls with no effect are consistent (controls)") {
  int consistent = 0;
  std::uint64_t seed = 100;
  for (const auto& spec : kMaterials) {
    seed += 5;
    const auto c = diagnosis::diagnose_against_passivity(synthetic(spec, {}, seed), kTube, 0);
    if (c.verdict == "consistent") ++consistent;
    else MESSAGE(fmt::format("{} passive: {}", spec, c.verdict));
  }
  CHECK(consistent == 5);
}

}  // TEST_SUITE("statistical")

}  // namespace admitgen::test

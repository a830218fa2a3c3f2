// SPDX-License-Identifier: MIT
// The other route of the four-effect and partner sweeps (validation_cases.hpp other_route_y) against
// synth's pipeline (physics/synthetic_measurement.hpp): its chain, written out from the pressure field in
// another order, must be the same physics as synth's one true chain (1e-11 relative: both evaluate the
// ISO inversion in double, amplified ≤ 18× near sin ks = 0 outside this band); its sample effects in the
// reverse order differ from synth's by the slit's area share of the resonance, which a frame resonance of
// y_peak·(1 − ε) in synth's order reproduces to the same tolerance (ε = 1 − (1 − 2w/d)², docs/cli.md).
#include "validation_cases.hpp"

#include <doctest/doctest.h>

#include <cmath>

namespace admitgen::test {
namespace {

SynthesisRequest request(const std::vector<std::string>& effects, const TubeSetup& tube) {
  SynthesisRequest r{parse_material_spec("delany_bazley(sigma=20000, d=40mm)"), {}, log_spaced_frequencies(100.0, 2000.0, 120),
                     0.0, 1, tube};
  for (const auto& e : effects) r.effects.push_back(parse_effect(e));
  return r;
}

double relative_difference(const Eigen::ArrayXcd& a, const Eigen::ArrayXcd& b) {
  return (a - b).abs().maxCoeff() / b.abs().maxCoeff();
}

}  // namespace

TEST_CASE("other route: the chain from the pressure field is synth's one true chain") {
  const TubeSetup reference{0.1, 0.05, 0.1, 20.0}, narrow{0.029, 0.05, 0.3, 20.0};
  for (const auto& [effects, tube] :
       std::vector<std::pair<std::vector<std::string>, TubeSetup>>{
           {{"reference_plane:delta_m=3mm"}, reference},
           {{"mic_spacing:delta_m=1mm", "mic_mismatch:gain=0.15,phase_deg=2"}, reference},
           {{"mic_mismatch:gain=0.03,phase_deg=1", "reference_plane:delta_m=3mm", "temperature:delta_k=8"}, reference},
           {{"tube_losses", "mic_spacing:delta_m=1mm", "air_gap:gap_m=3mm", "reference_plane:delta_m=-2mm"}, narrow}}) {
    const SynthesisRequest r = request(effects, tube);
    CAPTURE(effects.front());
    CHECK(relative_difference(other_route_y(r), synthesize(r).y) < 1e-11);
  }
}

TEST_CASE("other route: sample effects in the reverse order are synth's with the resonance scaled by the slit's share") {
  const TubeSetup tube{0.1, 0.05, 0.1, 20.0};
  const double w = 1e-3, d = 0.1, share = 1.0 - std::pow(1.0 - 2.0 * w / d, 2);
  const SynthesisRequest reversed = request({"edge_gap:width_m=1mm,depth_m=0.04", "frame_resonance:f0_hz=600,q=8,y_peak=0.1"}, tube);
  const SynthesisRequest scaled = request(
      {"edge_gap:width_m=1mm,depth_m=0.04", fmt::format("frame_resonance:f0_hz=600,q=8,y_peak={}", 0.1 * (1.0 - share))}, tube);
  CHECK(relative_difference(other_route_y(reversed), synthesize(scaled).y) < 1e-11);
  // Not synth's own order: the difference is the slit's share of the resonance, y_peak·ε at f0.
  CHECK(relative_difference(other_route_y(reversed), synthesize(reversed).y) > 1e-4);
}

}  // namespace admitgen::test

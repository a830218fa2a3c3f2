// SPDX-License-Identifier: MIT
// End-to-end `admitgen synth`: the CSV reads back through `fit`'s reader bit for bit, its comments carry
// the provenance, and bad input exits 2 with a message and leaves no file behind.
#include "data/csv_reader.hpp"
#include "physics/material_spec.hpp"
#include "physics/synthetic_measurement.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

namespace admitgen {
namespace {

TEST_CASE("synth CLI: output reads back exactly with fit's default options and records its provenance") {
  const std::string dir = test::scratch_dir("synth_cli_ok");
  const std::string out = dir + "/miki.csv";
  const auto r = test::run_admitgen("synth --material 'miki(sigma=10000, d=50mm) + air(d=20mm)' --effect "
                                    "frame_resonance:f0_hz=600,q=8,y_peak=0.3 --effect tube_losses --tube-diameter 0.1 "
                                    "--mic-spacing 0.05 --mic-distance 0.1 --noise 0.01 --seed 7 --band 200:1800 "
                                    "--points 50 --out '" + out + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::string text = test::read_text(out);
  CHECK(text.find("# material: miki(sigma=10000, d=50mm) + air(d=20mm)\n") != std::string::npos);
  CHECK(text.find("# effects: frame_resonance:f0_hz=600,q=8,y_peak=0.3 tube_losses\n") != std::string::npos);
  CHECK(text.find("# noise: complex Gaussian, std 0.01") != std::string::npos);
  CHECK(text.find("# seed: 7\n") != std::string::npos);

  // The same request through the library: the file holds exactly these doubles (%.17g round-trips).
  SynthesisRequest request{parse_material_spec("miki(sigma=10000, d=50mm) + air(d=20mm)"),
                           {parse_effect("frame_resonance:f0_hz=600,q=8,y_peak=0.3"), parse_effect("tube_losses")},
                           log_spaced_frequencies(200.0, 1800.0, 50),
                           0.01,
                           7,
                           TubeSetup{0.1, 0.05, 0.1, 20.0}};
  const Synthesis expected = synthesize(request);
  const Measurement read = read_measurement(out, ReadOptions{});
  REQUIRE(read.size() == 50);
  CHECK((read.f_hz == request.f_hz).all());
  CHECK((read.y == expected.y).all());
}

TEST_CASE("synth CLI: bad input exits 2 with a clear message and writes nothing") {
  const std::string dir = test::scratch_dir("synth_cli_bad");
  const std::string out = dir + "/never.csv";
  struct Case {
    std::string args;
    std::string message;
  };
  const Case cases[] = {
      {"--material 'mikki(sigma=1e4,d=5cm)'", "unknown layer 'mikki'"},
      {"--material 'miki(sigma=1e4)'", "missing parameter 'd'"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect mic_spacing:delta_m=1mm", "missing: --tube-diameter, --mic-spacing, --mic-distance"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect tube_losses --tube-diameter 0.1 --mic-spacing 0.05",
       "missing: --mic-distance"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect edge_gap:width_m=1mm,depth_m=5cm", "needs --tube-diameter"},
      {"--material 'multipole(G_inf=0.5)' --effect air_gap:gap_m=1mm", "needs a layered material"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect heteroscedastic_noise:scale=0.1 --tube-diameter 0.1 "
       "--mic-spacing 0.05 --mic-distance 0.1",
       "give --noise"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect frame_resonance:f0_hz=600", "missing parameter 'q'"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect warp:factor=2", "unknown effect 'warp'"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect tube_losses --effect tube_losses --tube-diameter 0.1 "
       "--mic-spacing 0.05 --mic-distance 0.1",
       "given twice"},
      {"--material 'miki(sigma=1e4,d=5cm)' --effect tube_losses --tube-diameter 0.1 --mic-spacing 0.2 --mic-distance 0.1",
       "--mic-spacing 0.2 m must be less than --mic-distance"},
      {"--material 'miki(sigma=1e4,d=5cm)' --band 4000:100", "FMAX must exceed FMIN"},
      {"--material 'miki(sigma=1e4,d=5cm)' --noise -0.1", "noise std must be >= 0"},
      {"--material 'miki(sigma=1e4,d=5cm)' --temperature 500", "outside -100..200"},
      {"--material 'fit(file=/nonexistent/fit.json)'", "cannot open fit.json"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.args);
    const auto r = test::run_admitgen("synth " + c.args + " --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(c.message) != std::string::npos);
    CHECK(!std::filesystem::exists(out));
  }
  const auto unwritable = test::run_admitgen("synth --material 'miki(sigma=1e4,d=5cm)' --out /nonexistent-dir/x.csv");
  CHECK(unwritable.exit_code == 2);
  CHECK(unwritable.output.find("cannot write '/nonexistent-dir/x.csv'") != std::string::npos);
}

}  // namespace
}  // namespace admitgen

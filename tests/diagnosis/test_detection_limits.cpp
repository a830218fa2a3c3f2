// SPDX-License-Identifier: MIT
// Detection limit of each effect at the suite's noise (σ = 0.003, 120 points 100-2000 Hz, porous base
// miki(sigma=10000, d=50mm), reference tube): the smallest size on a ladder from which every larger
// size is identified (top-1 verdict) for each of three noise seeds. Several minutes of sampling, so it
// is skipped unless asked for:
//   admitgen_tests -tc='detection limits*' --no-skip
// Its output is the detection-limit table of docs/diagnosis.md.
#include "validation_cases.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

namespace admitgen::test {
namespace {

struct Ladder {
  std::string effect;
  std::string size_name;
  std::vector<double> sizes;  ///< ascending
  std::function<ValidationCase(double)> make;
};

ValidationCase porous_case(const std::string& truth, const std::string& effect) {
  ValidationCase c;
  c.truth = truth;
  c.effect = effect;
  c.material = base_materials()[0];
  c.label = effect;
  return c;
}

std::vector<Ladder> ladders() {
  const auto simple = [](std::string name, std::string key, std::string unit_name, std::vector<double> sizes,
                         std::string suffix = "") {
    return Ladder{name, unit_name, sizes, [name, key, suffix](double v) {
                    return porous_case(name, fmt::format("{}:{}={}{}", name, key, v, suffix));
                  }};
  };
  std::vector<Ladder> out;
  out.push_back(simple("reference_plane", "delta_m", "delta [m]", {2e-5, 5e-5, 1e-4, 2e-4, 5e-4}));
  out.push_back(simple("mic_spacing", "delta_m", "delta [m]", {1e-5, 2e-5, 5e-5, 1e-4, 2e-4}));
  out.push_back({"mic_mismatch", "gain (phase_deg = 40 gain)", {2e-4, 5e-4, 1e-3, 2e-3, 5e-3}, [](double g) {
                   return porous_case("mic_mismatch", fmt::format("mic_mismatch:gain={},phase_deg={}", g, 40 * g));
                 }});
  out.push_back(simple("temperature", "delta_k", "delta [K]", {0.1, 0.2, 0.5, 1.0, 2.0}));
  // tube_losses has no parameter: its size is α_K x1 ∝ x1/d; the ladder is (0.1 m)/d at x1 = 0.1 m.
  out.push_back({"tube_losses", "0.1 m / d (x1 = 0.1 m)", {0.125, 0.25, 0.5, 1.0}, [](double v) {
                   ValidationCase c = porous_case("tube_losses", "tube_losses");
                   c.tube_diameter_m = 0.1 / v;
                   return c;
                 }});
  out.push_back(simple("edge_gap", "width_m", "width [m] (depth 50 mm)", {5e-5, 1e-4, 2e-4, 3e-4}, ",depth_m=0.05"));
  out.push_back(simple("frame_resonance", "y_peak", "y_peak (f0 600 Hz, q 8)", {1e-3, 2e-3, 5e-3, 1e-2, 2e-2}));
  // frame_resonance's key order: f0 and q first.
  out.back().make = [](double v) {
    return porous_case("frame_resonance", fmt::format("frame_resonance:f0_hz=600,q=8,y_peak={}", v));
  };
  out.push_back({"fractional_order", "c_plus (c_minus = 0.4 c_plus, f_ref 1 kHz)", {2e-4, 5e-4, 1e-3, 2e-3, 5e-3},
                 [](double v) {
                   return porous_case("fractional_order", fmt::format("fractional_order:c_plus={},c_minus={},f_ref_hz=1000",
                                                                      v, 0.4 * v));
                 }});
  out.push_back(simple("air_gap", "gap_m", "gap [m]", {5e-5, 1e-4, 2e-4, 5e-4}));
  out.push_back(simple("heteroscedastic_noise", "scale", "scale", {0.1, 0.15, 0.2, 0.3}));
  return out;
}

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("detection limits of every effect at the suite's noise" * doctest::skip()) {
    std::string table = "\n| effect | size | ladder (correct seeds of 3) | detection limit |\n|---|---|---|---|";
    for (const auto& ladder : ladders()) {
      std::vector<int> correct;
      std::string cells;
      for (double size : ladder.sizes) {
        int n = 0;
        for (std::uint64_t seed : {11, 12, 13}) {
          ValidationCase c = ladder.make(size);
          c.seed = seed;
          n += run_case(c).verdict.effect == ladder.effect;
        }
        correct.push_back(n);
        cells += fmt::format("{:g}: {}/3; ", size, n);
      }
      std::string limit = "above the ladder";
      for (std::size_t i = ladder.sizes.size(); i-- > 0;) {
        if (correct[i] != 3) break;
        limit = fmt::format("{:g}", ladder.sizes[i]);
      }
      table += fmt::format("\n| {} | {} | {}| {} |", ladder.effect, ladder.size_name, cells, limit);
    }
    MESSAGE(table);
  }
}

}  // namespace admitgen::test

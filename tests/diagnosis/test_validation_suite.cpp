// SPDX-License-Identifier: MIT
// The diagnosis validation suite (docs/diagnosis.md): generated cases of every documented effect at a
// clear and a marginal size on three base materials, plus clean controls; `diagnose` is never told the
// effect (an air gap behind a SPEC's air cavity counts as the material candidate of that cavity's d).
// Prints the confusion matrix; asserts top-1 accuracy ≥ 90 % on the clear sizes, `none` on ≥ 90 % of the
// controls, the signature frequency inside the worst band, and shrink ≥ 3× overall and
// ≥ 5× in the worst band for every correctly identified clear case (heteroscedastic_noise excepted:
// it changes the noise, not the mean, so no gap can shrink; its evidence is in the likelihood).
#include "validation_cases.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <map>
#include <set>

namespace admitgen::test {
namespace {

std::vector<ValidationCase> validation_cases() {
  std::vector<ValidationCase> cases;
  const double f0[] = {600.0, 850.0, 1200.0};  // frame resonances, away from band edges
  std::uint64_t seed = 100;
  for (std::size_t k = 0; k < base_materials().size(); ++k) {
    const BaseMaterial& m = base_materials()[k];
    for (const auto& e : effect_sizes(m, f0[k]))
      for (bool clear : {true, false}) {
        ValidationCase c;
        c.truth = e.name;
        c.effect = clear ? e.clear : e.marginal;
        c.material = m;
        c.clear = clear;
        c.seed = ++seed;
        // tube_losses has no size of its own: the attenuation e^{−2 α_K x1}, α_K ∝ 1/d, grows with the
        // path to the far microphone over the diameter; the clear case is a 29 mm tube with x1 = 0.3 m.
        if (e.name == "tube_losses" && clear) {
          c.tube_diameter_m = 0.029;
          c.mic_distance_m = 0.3;
        }
        if (e.name == "frame_resonance") c.signature_hz = f0[k];
        // A gap behind a SPEC's air cavity is that cavity made deeper: the material candidate of its d
        // (effect_candidates.hpp), which diagnose then names.
        if (e.name == "air_gap" && m.name != "porous") {
          c.truth = "material";
          c.parameter = "2.d";
        }
        // The slit's quarter-wave resonance c0/4h (docs/physics.md §5.1 f), where it lies inside the band.
        if (e.name == "edge_gap" && 343.2 / (4 * m.thickness_m) < 2000.0) c.signature_hz = 343.2 / (4 * m.thickness_m);
        c.label = fmt::format("{} {} {}", m.name, clear ? "clear" : "marginal", c.effect);
        cases.push_back(c);
      }
    for (int i = 0; i < 4; ++i) {
      ValidationCase c;
      c.truth = "none";
      c.material = m;
      c.seed = ++seed;
      c.label = fmt::format("{} control seed {}", m.name, c.seed);
      cases.push_back(c);
    }
  }
  return cases;
}

struct Tally {
  int right = 0;
  int total = 0;
  double rate() const { return total == 0 ? 1.0 : static_cast<double>(right) / total; }
};

void print_confusion(const std::map<std::string, std::map<std::string, int>>& m, const std::string& title) {
  std::set<std::string> columns;
  for (const auto& [truth, row] : m)
    for (const auto& [called, n] : row) columns.insert(called);
  std::string text = fmt::format("\n{}\n{:<22}", title, "truth \\ verdict");
  for (const auto& c : columns) text += fmt::format(" {:>6.6}", c);
  for (const auto& [truth, row] : m) {
    text += fmt::format("\n{:<22}", truth);
    for (const auto& c : columns) text += fmt::format(" {:>6}", row.count(c) ? std::to_string(row.at(c)) : ".");
  }
  MESSAGE(text);
}

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("diagnosis validation suite: confusion matrix, accuracy, controls, worst band, shrink") {
    const auto cases = validation_cases();
    REQUIRE(cases.size() >= 50);
    std::map<std::string, std::map<std::string, int>> clear_matrix, marginal_matrix;
    Tally clear, controls, marginal;
    std::string log;
    for (const auto& c : cases) {
      const auto d = run_case(c);
      const std::string called = d.verdict.effect;
      const bool right = called == c.truth && (c.parameter.empty() || d.verdict.explanation.front().parameters.front().first == c.parameter);
      log += fmt::format("\n{:<100} -> {:<22} BF {:7.1f} dB  shrink {:6.2f}  worst band {:5.0f} Hz", c.label, called,
                         d.verdict.bayes_factor_deciban, d.verdict.shrink, d.gap.bands[d.gap.worst].band.f_center);
      if (c.truth == "none") {
        ++controls.total;
        controls.right += right;
        ++clear_matrix[c.truth][called];
        continue;
      }
      (c.clear ? clear_matrix : marginal_matrix)[c.truth][called]++;
      Tally& t = c.clear ? clear : marginal;
      ++t.total;
      t.right += right;
      if (!(c.clear && right)) continue;
      CAPTURE(c.label);
      const auto& worst = d.gap.bands[d.gap.worst];
      if (c.signature_hz > 0.0) CHECK(worst.band.contains(c.signature_hz));
      if (c.truth == "heteroscedastic_noise") continue;
      const auto& top = d.identification.effects.front();
      CHECK(top.shrink >= 3.0);
      CHECK(worst.gap / top.gap_after.bands[d.gap.worst].gap >= 5.0);
    }
    MESSAGE(log);
    print_confusion(clear_matrix, "confusion matrix, clear sizes and controls (rows: truth, columns: verdict)");
    print_confusion(marginal_matrix, "confusion matrix, marginal sizes");
    MESSAGE(fmt::format("top-1 accuracy clear {}/{} = {:.0f} %, marginal {}/{} = {:.0f} %; controls called none {}/{} = {:.0f} %",
                        clear.right, clear.total, 100 * clear.rate(), marginal.right, marginal.total,
                        100 * marginal.rate(), controls.right, controls.total, 100 * controls.rate()));
    CHECK(clear.total >= 30);
    CHECK(controls.total >= 10);
    CHECK(clear.rate() >= 0.9);
    CHECK(controls.rate() >= 0.9);
  }
}

}  // namespace admitgen::test

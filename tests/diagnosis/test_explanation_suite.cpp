// SPDX-License-Identifier: MIT
// The compact validation of combined explanations, catalogue parameters and out-of-vocabulary gaps
// (docs/diagnosis.md, "Validation"); the full sweep with its tables is bench/diagnose/bench_validation.cpp.
// Fixed seeds (explanation_cases.hpp). Asserted: catalogue parameters named with the ratio within 30 %
// in log on ≥ 80 % of all catalogue cases (each takes a second or two: one round, white at once); one
// two-effect case with both effects named and the combined shrink ≥ half the exact model's; one
// out-of-vocabulary case (a microphone ratio drifting with frequency, no single effect halving its gap)
// called unexplained. The two-effect and out-of-vocabulary cases are single decisive examples, not
// rates: each costs tens of seconds (docs/diagnosis.md), the rates are the bench's.
#include "explanation_cases.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

namespace admitgen::test {

TEST_SUITE("statistical") {
  TEST_CASE("explanation suite: a catalogue parameter off is named, with its ratio within 30 % in log") {
    int right = 0, total = 0;
    std::string log;
    for (const auto& c : material_cases()) {
      const auto d = run_case(c);
      const double r = material_ratio(d.verdict, c.parameter);
      const bool ok = d.verdict.effect == "material" && r > 0.0 && std::abs(std::log(r / c.ratio)) <= std::log(1.3);
      log += fmt::format("\n{:<45} -> {} {} = {:.3f}", c.label, d.verdict.effect, c.parameter, r);
      ++total;
      right += ok;
    }
    MESSAGE(log);
    MESSAGE(fmt::format("material: {}/{} right", right, total));
    CHECK(total >= 12);
    CHECK(right >= 0.8 * total);
  }

  TEST_CASE("explanation suite: two effects at once are both named, the combined shrink at least half the exact model's") {
    const auto cases = two_effect_cases();
    const auto c = *std::find_if(cases.begin(), cases.end(), [](const ValidationCase& x) {
      return x.truth == "reference_plane" && x.truth_second == "tube_losses";
    });
    const auto d = run_case(c);
    CAPTURE(d.verdict.effect);
    CHECK(explains(d.verdict, c.truth));
    CHECK(explains(d.verdict, c.truth_second));
    CHECK(d.verdict.white_after);
    CHECK(d.verdict.shrink >= 0.5 * exact_shrink(c, d));
    CHECK(best_single_shrink(d) < 0.5 * d.verdict.shrink);  // neither effect alone comes close
  }

  TEST_CASE("explanation suite: a gap outside the vocabulary is unexplained") {
    const auto cases = out_of_vocabulary_cases();
    const auto c = *std::find_if(cases.begin(), cases.end(), [](const ValidationCase& x) {
      return x.label == "oov porous mic drift 15 % / 4 deg at the top";
    });
    const auto d = run_case(c);
    CHECK(best_single_shrink(d) < 2.0);  // counted by the criterion: no single effect halves the gap
    CHECK(d.verdict.effect == "unexplained");
    CHECK_FALSE(d.verdict.explanation.empty());  // the best attempt is reported
  }
}

}  // namespace admitgen::test

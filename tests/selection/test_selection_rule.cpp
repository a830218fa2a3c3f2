// SPDX-License-Identifier: MIT
// Selection rules and Bayes factors in deciban.
#include "core/errors.hpp"
#include "selection/fit.hpp"
#include "selection/selection_rule.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace admitgen;

TEST_CASE("deciban: 10 log10 of the evidence ratio") {
  CHECK(deciban(std::log(10.0), 0.0) == doctest::Approx(10.0).epsilon(1e-15));
  CHECK(deciban(0.0, std::log(100.0)) == doctest::Approx(-20.0).epsilon(1e-15));
}

TEST_CASE("selection: best evidence vs cheapest within a margin (the paper's Q1S1 vs Q0S2 argument)") {
  // Q1S1 (3 buffers) is 3.1 dB below Q0S2 (4 buffers); Q3S3 (9 buffers) is 1 dB above Q0S2.
  const double ln10 = std::log(10.0);
  const std::vector<double> log_z{0.0, -0.31 * ln10, 0.1 * ln10, -5.0 * ln10};
  const std::vector<int> buffers{4, 3, 9, 2};
  CHECK(SelectionRule::parse("best").select(log_z, buffers) == 2);
  CHECK(SelectionRule::parse("cheapest:5").select(log_z, buffers) == 1);   // Q1S1 within 4.1 dB of the best
  CHECK(SelectionRule::parse("cheapest:60").select(log_z, buffers) == 3);  // everything within 60 dB: 2 buffers
  CHECK(SelectionRule::parse("cheapest:0").select(log_z, buffers) == 2);
  CHECK_THROWS_AS(SelectionRule::parse("cheapest:-1"), InputError);
  CHECK_THROWS_AS(SelectionRule::parse("cheapest"), InputError);
  CHECK_THROWS_AS(SelectionRule::parse("worst"), InputError);
}

TEST_CASE("missed-mode check: a containing order with a lower best likelihood is flagged") {
  const auto model = [](int q, int s, double max_log_l) {
    ModelResult m{Order(q, s), {}, 0, 0.0, {}, {}};
    m.run.max_log_likelihood = max_log_l;
    return m;
  };
  // Q1S1 contains Q0S1 and Q1S0; Q0S2 contains Q0S1 only. Q1S1's 100 < Q0S1's 150: flagged.
  const std::vector<ModelResult> models{model(0, 1, 150.0), model(1, 0, 90.0), model(1, 1, 100.0), model(0, 2, 149.0)};
  const auto w = missed_mode_warnings(models, 2.0);
  REQUIRE(w.size() == 1);
  CHECK(w[0].rfind("Q1S1:", 0) == 0);
  CHECK(w[0].find("Q0S1") != std::string::npos);
  CHECK(missed_mode_warnings(models, 60.0).empty());
}

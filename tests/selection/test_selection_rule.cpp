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
  const std::vector<double> errors(4, 0.0);
  const std::vector<int> buffers{4, 3, 9, 2};
  CHECK(SelectionRule::parse("best").select(log_z, errors, buffers) == 2);
  CHECK(SelectionRule::parse("cheapest:5").select(log_z, errors, buffers) == 1);   // Q1S1 within 4.1 dB of the best
  CHECK(SelectionRule::parse("cheapest:60").select(log_z, errors, buffers) == 3);  // everything within 60 dB: 2 buffers
  CHECK(SelectionRule::parse("cheapest:0").select(log_z, errors, buffers) == 2);
  CHECK_THROWS_AS(SelectionRule::parse("cheapest:-1"), InputError);
  CHECK_THROWS_AS(SelectionRule::parse("cheapest"), InputError);
  CHECK_THROWS_AS(SelectionRule::parse("worst"), InputError);
  CHECK_THROWS_AS(SelectionRule::parse("simplest:x"), InputError);
}

TEST_CASE("selection: simplest within a margin plus two errors of the difference") {
  // Best: index 2 (9 buffers) at 0. Index 0 (4 buffers) 2.5 nats below (10.9 dB), index 1 (3 buffers) 3.9 nats
  // below (16.9 dB), index 3 (2 buffers) 30 nats below.
  const std::vector<double> log_z{-2.5, -3.9, 0.0, -30.0};
  const std::vector<int> buffers{4, 3, 9, 2};
  // Exact evidence: simplest:10 allows ln 10 = 2.303 nats, so neither 0 nor 1 qualifies: the best.
  CHECK(SelectionRule::parse("simplest:10").select(log_z, {0.0, 0.0, 0.0, 0.0}, buffers) == 2);
  // Errors 0.1 each: 2.303 + 2·√0.02 = 2.586 nats: index 0 qualifies (2.5), index 1 (3.9) does not.
  CHECK(SelectionRule::parse("simplest:10").select(log_z, {0.1, 0.1, 0.1, 0.1}, buffers) == 0);
  // Errors 0.6: 2.303 + 2·√0.72 = 4.00 nats: index 1 qualifies; index 3 never.
  CHECK(SelectionRule::parse("simplest:10").select(log_z, {0.6, 0.6, 0.6, 0.6}, buffers) == 1);
  // cheapest:10 ignores the errors.
  CHECK(SelectionRule::parse("cheapest:10").select(log_z, {0.6, 0.6, 0.6, 0.6}, buffers) == 2);
  CHECK(SelectionRule::parse("simplest:10").spelling() == "simplest:10");
}

TEST_CASE("selection: target ships the fewest buffers that meet it, undetermined or over-budget orders are never chosen") {
  // Indices: 0 = 4 buffers meets, 1 = 3 buffers misses, 2 = 9 buffers meets (best evidence), 3 = 2 buffers meets
  // but its runs disagree (unusable). Evidence as in the previous case.
  const std::vector<double> log_z{-2.5, -3.9, 0.0, -30.0};
  const std::vector<double> errors(4, 0.1);
  const std::vector<int> buffers{4, 3, 9, 2};
  const std::vector<bool> all(4, true);
  const SelectionRule target = SelectionRule::parse("target");
  CHECK(target.spelling() == "target");
  // Every order usable: index 3 (2 buffers) meets and is cheapest, whatever its evidence.
  CHECK(target.select(log_z, errors, buffers, {true, false, true, true}, all) == 3);
  // Index 3 unusable: index 0 (4 buffers) is the cheapest that meets; 1 is cheaper but misses.
  CHECK(target.select(log_z, errors, buffers, {true, false, true, true}, {true, true, true, false}) == 0);
  // Equal buffers: the higher evidence.
  CHECK(target.select({-1.0, 0.0}, {0.0, 0.0}, {4, 4}, {true, true}, {true, true}) == 1);
  // None meets: simplest:10 decides (with errors 0.1 index 0 qualifies, as in the previous case).
  CHECK(target.select(log_z, errors, buffers, {false, false, false, false}, all) == 0);
  // The evidence rules skip unusable orders too: best without index 2 is index 0.
  CHECK(SelectionRule::parse("best").select(log_z, errors, buffers, {false, false, false, false},
                                           {true, true, false, true}) == 0);
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

TEST_CASE("missed-mode check: a re-run that left ln Z in place turns a small gap into a note, never a large one") {
  ModelResult small{Order(1, 2), {}, 0, 0.0, {}, {}}, big{Order(1, 3), {}, 0, 0.0, {}, {}};
  const std::vector<ModelResult> models{small, big};
  // The gap is reference − own: 2.4 nats (the reference file's switched-off spare pairs) and 22.5 nats.
  const MissedMode near{1, 0, 1284.3, false, 1281.9, true}, far{1, 0, 1304.4, false, 1281.9, true};
  std::vector<ModelResult> rerun = models;
  // Shift 0.3 ± 0.25: within max(2 errors, 1 nat); shift 1.2 ± 0.25: beyond both.
  rerun[1].rerun = RerunCheck{0.3, 0.25, 500};
  CHECK(missed_mode_notes(rerun, {near}).size() == 1);
  CHECK(missed_mode_warnings(rerun, {near}).empty());
  CHECK(missed_mode_notes(rerun, {far}).empty());  // kMaxGapNats = 5: a 22.5-nat gap stays a warning
  CHECK(missed_mode_warnings(rerun, {far}).size() == 1);
  rerun[1].rerun = RerunCheck{1.2, 0.25, 500};
  CHECK(missed_mode_notes(rerun, {near}).empty());
  CHECK(missed_mode_warnings(rerun, {near}).size() == 1);
  // No re-run at all: a warning.
  CHECK(missed_mode_notes(models, {near}).empty());
  const auto w = missed_mode_warnings(models, {near});
  REQUIRE(w.size() == 1);
  CHECK(w[0].rfind("Q1S3:", 0) == 0);
}

TEST_CASE("disagreeing runs: an error of ln Z above the largest gap a note explains is a warning") {
  // runs_disagree_warnings flags an error above RerunCheck::kMaxGapNats (5 nats): 5.5 is flagged, 4.5 is not
  // (√(H/n) alone never comes near: H of a few hundred nats at 100 live points gives under 2).
  ModelResult agree{Order(4, 4), {}, 100, 0.0, {}, {}}, split{Order(4, 5), {}, 100, 0.0, {}, {}};
  agree.run.log_z_error = 4.5;
  split.run.log_z_error = 5.5;
  split.run.log_z = 8324.6;
  const auto w = runs_disagree_warnings({agree, split});
  REQUIRE(w.size() == 1);
  CHECK(w[0].rfind("Q4S5:", 0) == 0);
  CHECK(w[0].find("8324.6 ± 5.5") != std::string::npos);
  CHECK(w[0].find(setting("sampler.live")) != std::string::npos);  // the fix: more live points
}

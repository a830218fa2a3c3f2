// SPDX-License-Identifier: MIT
// The check report's writer (io/check_report.hpp): each check's typed figures under the keys of
// docs/formats.md, "check report", and the text form; a hand-built report, so every expected value here
// is written out independently of the checks that normally fill it.
#include "io/check_report.hpp"

#include <nlohmann/json.hpp>

#include <doctest/doctest.h>

#include <limits>

using namespace admitgen;

namespace {

checks::CheckReport sample_report() {
  const double inf = std::numeric_limits<double>::infinity();
  checks::CheckReport report{"wall.h", "header", {}};
  checks::CheckResult causality{"causality", "poles", checks::Status::pass, "2 pole(s)", {}, {}};
  causality.details = checks::CausalityDetails{std::nullopt};
  checks::CheckResult passivity{"passivity_discrete", "Hamiltonian", checks::Status::pass, "min Re H", {}, {}};
  PassivityResult p;
  p.passive = false;
  p.method = "test";
  p.crossings = {100.0};
  p.bands = {NegativeBand{100.0, inf, -0.5, inf}};
  p.min_re = -0.5;
  p.min_at = inf;
  passivity.details = checks::DiscretePassivityDetails{
      {{48000, checks::PassivityDetails{p, {checks::BandPlace::above}}}, {96000, std::nullopt}}};
  passivity.fail("fs 48000 Hz: Re G < 0");
  checks::CheckResult limit{"limit_cycle", "zero input", checks::Status::pass, "decays", {}, {}};
  limit.details = checks::LimitCycleDetails{{{48000, 296L, 296L}, {96000, std::nullopt, 10L}}};
  checks::CheckResult integrity{"header_integrity", "tables", checks::Status::not_applicable, "not a header", {}, {}};
  integrity.details = checks::HeaderIntegrityDetails{12};
  report.checks = {causality, passivity, limit, integrity};
  return report;
}

}  // namespace

TEST_CASE("check report JSON: typed figures under the documented keys, infinite frequencies as \"inf\"") {
  const std::string text = io::check_report_json(sample_report());
  REQUIRE(text.back() == '\n');
  const auto j = nlohmann::json::parse(text);
  CHECK(j["schema"] == "admitgen.check/1");
  CHECK(j["passed"] == false);
  CHECK(j["failed"] == nlohmann::json::array({"passivity_discrete"}));
  const auto& c = j["checks"];
  CHECK(c[0]["details"]["slowest_rate_per_s"].is_null());
  CHECK(c[1]["status"] == "fail");
  const auto& rate = c[1]["details"]["rates"][0];
  CHECK(rate["fs_hz"] == 48000);
  CHECK(rate["passive"] == false);
  CHECK(rate["crossings_hz"] == nlohmann::json::array({100.0}));
  CHECK(rate["negative_bands"][0]["f_hi_hz"] == "inf");
  CHECK(rate["negative_bands"][0]["at_hz"] == "inf");
  CHECK(rate["negative_bands"][0]["where"] == "above the data band");
  CHECK(rate["min_at_hz"] == "inf");
  CHECK(c[1]["details"]["rates"][1] == nlohmann::json({{"fs_hz", 96000}, {"skipped", "unstable (see discrete_stability)"}}));
  CHECK(c[2]["details"]["rates"][0] == nlohmann::json({{"fs_hz", 48000}, {"zero_decay_bound", 296}, {"simulated_samples", 296}}));
  CHECK(c[2]["details"]["rates"][1] == nlohmann::json({{"fs_hz", 96000}, {"simulated_samples", 10}}));
  CHECK(c[3]["status"] == "n/a");
  CHECK(c[3]["details"] == nlohmann::json::object());
}

TEST_CASE("check report text: a line per check, failures below it, the count of failed checks") {
  CHECK(io::check_report_text(sample_report()) ==
        "admitgen check wall.h (header)\n"
        "  pass causality              2 pole(s)\n"
        "  FAIL passivity_discrete     min Re H\n"
        "         - fs 48000 Hz: Re G < 0\n"
        "  pass limit_cycle            decays\n"
        "  n/a  header_integrity       not a header\n"
        "1 check(s) failed\n");
}

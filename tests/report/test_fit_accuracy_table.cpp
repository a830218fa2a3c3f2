// SPDX-License-Identifier: MIT
// The cost/accuracy table end to end (docs/method.md, "Accuracy target"): fit.json's per-order accuracy, the rule
// `target` read back from it, the budget, the terminal table and the report's figure.
#include "test_support.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <string>

using namespace admitgen::test;

TEST_CASE("fit: the target rule ships the fewest buffers whose passive estimate meets the target, within the budget") {
  const std::string data = sample("basotect_tuberlin/round_10cm.csv");
  // Q0-1 x S0-3 at 40 live points, no growth: seconds, and the bundled file's Q1S3 meets |Δα| ≤ 0.01 at 100 live
  // points (docs/method.md); whatever this smaller run gives, the checks below recompute the rule from fit.json.
  for (const int budget : {0, 5}) {
    const std::string dir = scratch_dir("accuracy_table_" + std::to_string(budget));
    const auto r = run_admitgen("fit '" + data + "' --columns f,_,_,_,_,re,im,_ --qmax 1 --smax 3 --grid-growth 0 "
                                "--live 40 --seed 3 --max-buffers " + std::to_string(budget) + " --out '" + dir + "'");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("band|Δα|") != std::string::npos);
    CHECK(r.output.find("±≥err") != std::string::npos);  // one run: the error is labelled a lower bound
    const auto fit = nlohmann::json::parse(read_text(dir + "/fit.json"));
    const double target = fit["settings"]["target"]["max_band_delta_alpha"].get<double>();
    CHECK(target == 0.01);
    CHECK(fit["log_evidence_error"].get<std::string>().find("lower bound") != std::string::npos);
    // The rule, recomputed: among orders within the budget that meet the target, fewest buffers, then highest ln Z.
    std::string expected;
    long best_buffers = 1000;
    double best_z = 0.0;
    for (const auto& m : fit["models"]) {
      const auto& a = m["accuracy"];
      const long buffers = a["buffers"].get<long>();
      CHECK(buffers == m["Q"].get<long>() + 2 * m["S"].get<long>());
      CHECK(a["meets_target"].get<bool>() == (a["max_band_delta_alpha"].get<double>() <= target));
      if (!a["meets_target"].get<bool>() || (budget > 0 && buffers > budget)) continue;
      const double z = m["log_evidence"].get<double>();
      if (buffers < best_buffers || (buffers == best_buffers && z > best_z)) {
        expected = m["order"].get<std::string>();
        best_buffers = buffers;
        best_z = z;
      }
    }
    // Without a budget Q1S3 meets the target here (a rule that cannot be checked would make this test vacuous).
    if (budget == 0) REQUIRE_FALSE(expected.empty());
    if (!expected.empty()) CHECK(fit["selected"]["order"].get<std::string>() == expected);
    for (const auto& m : fit["models"])
      if (m["order"] == fit["selected"]["order"] && budget > 0) CHECK(m["accuracy"]["buffers"].get<long>() <= budget);
    const std::string report = read_text(dir + "/report.html");
    CHECK(report.find("fig-accuracy") != std::string::npos);
    CHECK(report.find("meets target") != std::string::npos);
  }
}

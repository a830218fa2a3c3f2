// SPDX-License-Identifier: MIT
// Every filter the suite emits from a fit of real data passes `admitgen check`.
// The fit is committed (samples/fits/basotect_round_10cm_passive, made by
//   admitgen fit samples/basotect_tuberlin/round_10cm.csv --columns f,_,_,_,_,re,im,_ --qmax 1 --smax 3
//            --live 100 --passive --out samples/fits/basotect_round_10cm_passive
// ) so that the test is quick; the --passive fit restricts the posterior to passive models, and emit
// picks, per rate, a refit whose discrete response stays passive up to Nyquist.
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <string>

using namespace admitgen;

TEST_CASE("real data: every filter emitted from the passive Basotect fit passes check") {
  const std::string fit = test::sample("fits/basotect_round_10cm_passive/fit.json");
  const auto settings = nlohmann::json::parse(test::read_text(fit))["settings"];
  REQUIRE(settings.contains("passive"));  // a description string, present only for --passive fits
  const auto whole = test::run_admitgen("check '" + fit + "'");
  INFO(whole.output);
  CHECK(whole.exit_code == 0);
  const std::string dir = test::scratch_dir("real_data_filters");
  int emitted = 0;
  for (const char* format : {"f32", "q31", "q15"})
    for (const char* estimate : {"mean", "max_likelihood"}) {
      const std::string header = dir + "/wall_" + format + "_" + estimate + ".h";
      const auto e = test::run_admitgen("emit '" + fit + "' --fs 48000 --fs 44100 --fs 96000 --format " + format +
                                        " --estimate " + estimate + " --out '" + header + "'");
      INFO(format, " ", estimate, "\n", e.output);
      REQUIRE(e.exit_code == 0);
      const auto c = test::run_admitgen("check '" + header + "'");
      INFO(c.output);
      CHECK(c.exit_code == 0);
      CHECK(c.output.find("all checks passed") != std::string::npos);
      ++emitted;
    }
  CHECK(emitted == 6);
}

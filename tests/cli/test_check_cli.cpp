// SPDX-License-Identifier: MIT
// `admitgen check` and the emit refusal, end to end (exit codes of docs/cli.md).
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <doctest/doctest.h>

#include <filesystem>

using namespace admitgen;

TEST_CASE("admitgen check: exit 0 for a good header and fit, 1 naming the failure, 2 for unusable input") {
  const std::string dir = test::scratch_dir("check_cli");
  const std::string fit = test::sample("fits/q1s1_reference.json");
  auto r = test::run_admitgen("emit '" + fit + "' --fs 48000 --format q31 --out " + dir + "/wall.h --quiet");
  REQUIRE(r.exit_code == 0);
  r = test::run_admitgen("check " + dir + "/wall.h");
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("all checks passed") != std::string::npos);
  r = test::run_admitgen("check " + dir + "/wall.h --json");
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.output);
  CHECK(j["schema"] == "admitgen.check/1");
  CHECK(j["checks"].size() == 8);
  CHECK(test::run_admitgen("check '" + fit + "'").exit_code == 0);

  // At 24 kHz the most accurate refit is not passive above the data band (Re H < 0 over 8.2-8.7 kHz);
  // emit picks the passive candidate instead, and check confirms it.
  r = test::run_admitgen("emit '" + fit + "' --fs 24000 --format f32 --out " + dir + "/w24.h");
  CHECK(r.exit_code == 0);
  CHECK(test::run_admitgen("check " + dir + "/w24.h").exit_code == 0);
  // With the FIR length forced to 5 at 16 kHz no candidate is passive (taps and residues cancel in float,
  // whether refitted to the exact poles or to the poles as stored): emit refuses, writes nothing and names
  // the check; --allow-unsafe writes it.
  r = test::run_admitgen("emit '" + fit + "' --fs 16000 --fir-taps 5 --format f32 --out " + dir + "/w16.h");
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("passivity_discrete") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/w16.h"));
  r = test::run_admitgen("emit '" + fit + "' --fs 16000 --fir-taps 5 --format f32 --allow-unsafe --out " + dir + "/w16.h");
  CHECK(r.exit_code == 0);
  CHECK(r.output.find("warning: --allow-unsafe") != std::string::npos);
  r = test::run_admitgen("check " + dir + "/w16.h");
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("FAIL passivity_discrete") != std::string::npos);
  CHECK(r.output.find("309.45") != std::string::npos);  // the band edge in Hz

  test::write_text(dir + "/junk.h", "int x;\n");
  CHECK(test::run_admitgen("check " + dir + "/junk.h").exit_code == 2);
  CHECK(test::run_admitgen("check " + dir + "/missing.h").exit_code == 2);
  test::write_text(dir + "/other.json", "{\"schema\": \"something\"}");
  CHECK(test::run_admitgen("check " + dir + "/other.json").exit_code == 2);
}

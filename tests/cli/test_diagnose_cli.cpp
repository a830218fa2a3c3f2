// SPDX-License-Identifier: MIT
// `admitgen diagnose` end to end: the verdict on a synthetic frame resonance, byte-identical reruns with
// 1 and 2 threads, exit code 1 when the verdict names an effect and 0 when it is `none` (docs/cli.md:
// 1 = a diagnosis found a violation), exit code 2 and no output on bad input.
#include "test_support.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace admitgen::test {
namespace {

const std::string kMaterial = "'miki(sigma=10000, d=50mm)'";
const std::string kTube = " --tube-diameter 0.1 --mic-spacing 0.05 --mic-distance 0.1";

std::string make_real(const std::string& dir) {
  const std::string csv = dir + "/real.csv";
  const auto r = run_admitgen("synth --material " + kMaterial +
                              " --effect frame_resonance:f0_hz=700,q=8,y_peak=0.1 --noise 0.003 --band 200:1600 "
                              "--points 60 --seed 4 -q --out " + csv + kTube);
  REQUIRE(r.exit_code == 0);
  return csv;
}

}  // namespace

TEST_CASE("diagnose CLI: finds a frame resonance, writes diagnosis.json, byte-identical with 1 and 2 threads") {
  const std::string dir = scratch_dir("diagnose_cli");
  const std::string real = make_real(dir);
  const std::string args = "diagnose --real " + real + " --sim " + kMaterial + kTube + " --live 40 --out ";
  const auto first = run_admitgen(args + dir + "/a --threads 1");
  REQUIRE(first.exit_code == 1);  // the verdict names an effect: a gap with an identified cause
  CHECK(first.output.find("verdict: frame_resonance") != std::string::npos);
  const auto second = run_admitgen(args + dir + "/b -q --threads 2");
  REQUIRE(second.exit_code == 1);
  const std::string a = read_text(dir + "/a/diagnosis.json");
  CHECK(a == read_text(dir + "/b/diagnosis.json"));
  const auto j = nlohmann::json::parse(a);
  CHECK(j["schema"] == "admitgen.diagnosis/3");
  CHECK(j["verdict"]["effect"] == "frame_resonance");
  // One member: its share of the squared gap is the whole explained fraction (docs/diagnosis.md, "Main
  // cause"), computed the other way round (1 − 1/shrink²); both are ratios of the same sums, so 1e-12.
  REQUIRE(j["verdict"]["shares"].size() == 1);
  CHECK(std::abs(j["verdict"]["shares"][0]["share"].get<double>() - j["verdict"]["explained_fraction"].get<double>()) < 1e-12);
  CHECK(j["verdict"]["main_cause"]["effect"] == "frame_resonance");
  CHECK(j["verdict"]["dropped"].empty());
  CHECK(first.output.find("verdict: frame_resonance - main cause frame_resonance (") != std::string::npos);
  CHECK(first.output.find("shares of the squared gap: frame_resonance ") != std::string::npos);
  CHECK(j["effects"][0]["effect"] == "frame_resonance");
  CHECK(j["effects"][0]["parameters"]["f0_hz"].get<double>() == doctest::Approx(700.0).epsilon(0.02));
  CHECK(j["gap"]["bands"].size() > 5);
  CHECK(j["stages"].empty());
}

TEST_CASE("diagnose CLI: the simulated side as a CSV table") {
  const std::string dir = scratch_dir("diagnose_cli_table");
  const std::string real = make_real(dir);
  REQUIRE(run_admitgen("synth --material " + kMaterial + " --band 150:2000 --points 80 -q --out " + dir + "/sim.csv")
              .exit_code == 0);
  const auto r = run_admitgen("diagnose --real " + real + " --sim " + dir + "/sim.csv --live 40 -q --out " + dir + "/d");
  REQUIRE(r.exit_code == 1);
  const auto j = nlohmann::json::parse(read_text(dir + "/d/diagnosis.json"));
  CHECK(j["verdict"]["effect"] == "frame_resonance");
}

TEST_CASE("diagnose CLI: a --sim table in another layout is read with the --sim-* options") {
  // The same simulated admittance, rewritten as a tube program might: no header, a spare column, impedance
  // z = 1/y, ';' and decimal commas. The real file is read as before; --sim-columns and --sim-quantity
  // describe the sim table, and the diagnosis (all evidences, printed with 17 digits, so any other reading
  // would change them) must equal the one from the plain table. Without them the sim table's four columns
  // do not match the f,re,im the real file is read with: exit 2.
  const std::string dir = scratch_dir("diagnose_cli_sim_options");
  const std::string real = make_real(dir);
  REQUIRE(run_admitgen("synth --material " + kMaterial + " --band 150:2000 --points 80 -q --out " + dir + "/sim.csv")
              .exit_code == 0);
  std::ifstream in(dir + "/sim.csv");
  std::ofstream out(dir + "/sim_z.txt");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || !(std::isdigit(static_cast<unsigned char>(line[0])) != 0)) continue;
    double f = 0, re = 0, im = 0;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf", &f, &re, &im) == 3);
    const std::complex<double> z = 1.0 / std::complex<double>(re, im);
    std::string row = fmt::format("{:.17g};7;{:.17g};{:.17g}", f, z.real(), z.imag());
    std::replace(row.begin(), row.end(), '.', ',');
    out << row << "\n";
  }
  out.close();
  const std::string common = "diagnose --real " + real + " --live 40 -q";
  REQUIRE(run_admitgen(common + " --sim " + dir + "/sim.csv --out " + dir + "/plain").exit_code == 1);
  REQUIRE(run_admitgen(common + " --sim " + dir + "/sim_z.txt --sim-columns f,_,re,im --sim-quantity impedance --out " +
                       dir + "/other")
              .exit_code == 1);
  auto plain = nlohmann::json::parse(read_text(dir + "/plain/diagnosis.json"));
  auto other = nlohmann::json::parse(read_text(dir + "/other/diagnosis.json"));
  CHECK(other["verdict"]["effect"] == "frame_resonance");
  REQUIRE(other["effects"].size() == plain["effects"].size());
  for (std::size_t i = 0; i < plain["effects"].size(); ++i) {
    CAPTURE(i);
    CHECK(other["effects"][i]["effect"] == plain["effects"][i]["effect"]);
    // z = 1/y through 17-digit text and back changes y by a few ulp: evidences agree to 1e-9 relative.
    CHECK(other["effects"][i]["log_evidence"].get<double>() ==
          doctest::Approx(plain["effects"][i]["log_evidence"].get<double>()).epsilon(1e-9));
  }
  const auto bad = run_admitgen(common + " --sim " + dir + "/sim_z.txt --out " + dir + "/bad");
  CHECK(bad.exit_code == 2);
  CHECK(bad.output.find("--sim-columns") != std::string::npos);  // the fix for the --sim table, not --columns
  CHECK_FALSE(std::filesystem::exists(dir + "/bad"));
}

TEST_CASE("diagnose CLI: bad input exits 2 and writes nothing") {
  const std::string dir = scratch_dir("diagnose_cli_bad");
  const std::string real = make_real(dir);
  const std::string out = " --out " + dir + "/out";
  const std::vector<std::string> bad{
      "diagnose --real " + real + " --reference passive --sim " + kMaterial + out,        // passive takes no --sim
      "diagnose --real " + real + " --sim " + kMaterial + " --write-corrected c.csv" + out,  // needs the passive reference
      "diagnose --real " + real + " --tube-diameter 0.1" + out,                           // passive, partial geometry
      "diagnose --real " + real + " --fs 48000" + out,                                    // passive, --fs without --fit
      "diagnose --real " + real + " --sim 'miki(sigma=10000)'" + out,                    // incomplete SPEC
      "diagnose --real " + dir + "/missing.csv --sim " + kMaterial + out,                // missing file
      "diagnose --real " + real + " --sim " + kMaterial + " --fs 48000" + out,           // --fs without --fit
      "diagnose --real " + real + " --sim " + kMaterial + " --tube-diameter 0.1" + out,  // partial geometry
      "diagnose --real " + real + " --fit " + dir + "/real.csv" + out,                   // not a fit.json
  };
  for (const auto& args : bad) {
    CAPTURE(args);
    const auto r = run_admitgen(args);
    CHECK(r.exit_code == 2);
    CHECK_FALSE(std::filesystem::exists(dir + "/out/diagnosis.json"));
    CHECK_FALSE(std::filesystem::exists(dir + "/out/passive_diagnosis.json"));
  }
}

TEST_CASE("diagnose CLI: --fit with --fs reports the pipeline stages") {
  const std::string dir = scratch_dir("diagnose_cli_stages");
  const auto r = run_admitgen("diagnose --real " + sample("reference/q1s1_sigma0.01.csv") + " --fit " +
                              sample("fits/q1s1_reference.json") + " --fs 48000 --format q15 --live 30 -q --out " + dir);
  const auto j = nlohmann::json::parse(read_text(dir + "/diagnosis.json"));
  CHECK(r.exit_code == (j["verdict"]["effect"] == "none" ? 0 : 1));
  REQUIRE(j["stages"].size() == 4);
  CHECK(j["stages"][0]["stage"] == "fit");
  CHECK(j["stages"][2]["stage"] == "quantization");
  CHECK(j["stages"][3]["stage"] == "simulation");
  CHECK(j["stages"][3]["detail"].get<std::string>().find("1D FDTD tube") != std::string::npos);
}

TEST_CASE("diagnose CLI: a verdict of none exits 0") {
  // The measured side is the simulated material itself plus white noise (no effect): verdict none.
  const std::string dir = scratch_dir("diagnose_cli_none");
  REQUIRE(run_admitgen("synth --material " + kMaterial + " --noise 0.003 --band 200:1600 --points 60 --seed 5 -q --out " +
                       dir + "/real.csv" + kTube)
              .exit_code == 0);
  const auto r = run_admitgen("diagnose --real " + dir + "/real.csv --sim " + kMaterial + kTube + " --live 40 -q --out " + dir + "/d");
  const auto j = nlohmann::json::parse(read_text(dir + "/d/diagnosis.json"));
  CHECK(j["verdict"]["effect"] == "none");
  CHECK(r.exit_code == 0);
}

TEST_CASE("diagnose CLI: a parameter held by a prior bound is stated on the terminal and in diagnosis.json") {
  // A microphone calibration 40 % off, beyond the gain prior [-0.25, 0.25] (docs/diagnosis.md, "A parameter
  // at its prior's bound"): the gain sits at 0.25, and the summary and the file say so with the fix.
  const std::string dir = scratch_dir("diagnose_cli_bound");
  REQUIRE(run_admitgen("synth --material " + kMaterial + " --effect mic_mismatch:gain=0.4,phase_deg=2 --noise 0.003 "
                       "--band 200:1600 --points 60 --seed 6 -q --out " + dir + "/real.csv" + kTube)
              .exit_code == 0);
  const auto r = run_admitgen("diagnose --real " + dir + "/real.csv --sim " + kMaterial + kTube + " --live 40 --out " + dir + "/d");
  CHECK(r.exit_code == 1);
  CHECK(r.output.find("at its prior's bound: mic_mismatch gain = ") != std::string::npos);
  CHECK(r.output.find("calibrate the microphones") != std::string::npos);
  const auto j = nlohmann::json::parse(read_text(dir + "/d/diagnosis.json"));
  REQUIRE(j["verdict"].contains("at_prior_bound"));
  CHECK(j["verdict"]["at_prior_bound"][0]["effect"] == "mic_mismatch");
  CHECK(j["verdict"]["at_prior_bound"][0]["parameter"] == "gain");
  CHECK(j["verdict"]["at_prior_bound"][0]["bound"] == "upper");
  CHECK(j["verdict"]["at_prior_bound"][0]["bound_value"] == 0.25);
}

}  // namespace admitgen::test

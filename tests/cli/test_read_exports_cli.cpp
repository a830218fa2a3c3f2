// SPDX-License-Identifier: MIT
// Reading real exports through `admitgen fit`: the export catalogue end to end (exit 2, the
// documented message and nothing written for the bad ones), the two readings that used to succeed
// silently, no output directory left behind, and the goodness of fit in fit.json, summary and report.
#include "data/csv_reader.hpp"
#include "data/export_catalogue.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

using namespace admitgen::test;
namespace fs = std::filesystem;

namespace {

// Q0S0 with 10 live points: a few thousand likelihood calls, milliseconds; the reading is under test.
const std::string kQuickFit = " --qmax 0 --smax 0 --live 10 --seed 3";

struct Written {
  std::string data, out;
};

Written write_case(const std::string& dir, const Export& e) {
  const Written w{dir + "/" + e.file, dir + "/out_" + e.file + "/nested"};
  write_text(w.data, e.text);
  return w;
}

}  // namespace

TEST_CASE("fit cli: every export of the catalogue fits, or exits 2 with its message and leaves nothing behind") {
  const std::string dir = scratch_dir("read_exports_cli");
  for (const Export& e : export_catalogue(Reference())) {
    const Written w = write_case(dir, e);
    const auto r = run_admitgen("fit '" + w.data + "' " + e.flags + kQuickFit + " --out '" + w.out + "'");
    INFO(std::string(e.name), "\n", r.output);
    if (e.error.empty()) {
      CHECK(r.exit_code == 0);
      const auto fit = nlohmann::json::parse(read_text(w.out + "/fit.json"));
      CHECK(fit["input"]["points"] == 41);
      CHECK(fit["input"]["read_as"].get<std::string>().find("f = column") != std::string::npos);
    } else {
      CHECK(r.exit_code == 2);
      CHECK(r.output.find(e.error) != std::string::npos);
      CHECK_FALSE(fs::exists(fs::path(w.out).parent_path()));  // not even the (parent) directory
    }
  }
}

TEST_CASE("fit cli: the two readings that used to succeed silently now fail and name the fix") {
  const std::string dir = scratch_dir("read_silent_cases");
  const auto catalogue = export_catalogue(Reference());
  const auto find = [&](const char* file) {
    return *std::find_if(catalogue.begin(), catalogue.end(), [&](const Export& e) { return std::string(e.file) == file; });
  };
  const auto refused = [](const Written& w, const std::string& flags, const std::string& text) {
    const auto r = run_admitgen("fit '" + w.data + "' " + flags + kQuickFit + " --out '" + w.out + "'");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(text) != std::string::npos);
    CHECK_FALSE(fs::exists(fs::path(w.out).parent_path()));
  };
  // SI impedance (Pa s/m) read with --quantity impedance and no --rho-c: was a "rigid wall" at exit 0.
  const Written si = write_case(dir, find("z_si_silent.csv"));
  refused(si, "--quantity impedance", "--rho-c RHO_C");
  // The same data with --rho-c but without --quantity impedance: the hint says which option is missing.
  refused(si, "--rho-c 413.3", "read as --quantity impedance --rho-c 413.3, they are plausible");
  // e^{-iwt} data: was a 39 % residual at exit 0.
  const Written minus = write_case(dir, find("z_minus_silent.csv"));
  refused(minus, "", "give --time-convention -jwt");
  // Demoted to a warning on request: in fit.json (naming the setting by its field, as files do) and on
  // stderr (naming the flag), with the fit's poor goodness of fit.
  const auto d = run_admitgen("fit '" + minus.data + "' --no-plausibility-errors" + kQuickFit + " --out '" + minus.out + "'");
  INFO(d.output);
  CHECK(d.exit_code == 0);
  const auto fit = nlohmann::json::parse(read_text(minus.out + "/fit.json"));
  const std::string warnings = fit["warnings"].dump();
  CHECK(warnings.find("give time_convention=-jwt") != std::string::npos);
  CHECK(warnings.find("--") == std::string::npos);
  CHECK(warnings.find("fits poorly") != std::string::npos);
  CHECK(d.output.find("warning: " + minus.data + ": Im y < 0") != std::string::npos);
  CHECK(d.output.find("give --time-convention -jwt") != std::string::npos);
  CHECK(d.output.find("check how the data were read (--quantity, --rho-c, --time-convention)") != std::string::npos);
}

TEST_CASE("fit cli: an input error found after the output directory was made leaves no directory") {
  const std::string dir = scratch_dir("read_no_leftover");
  write_text(dir + "/few.csv", "100,0.1,0.2\n200,0.2,0.3\n300,0.3,0.4\n400,0.35,0.4\n");
  const auto r = run_admitgen("fit '" + dir + "/few.csv' --qmax 3 --smax 3 --out '" + dir + "/a/b/c'");
  INFO(r.output);
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("parameters but the data hold only") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/a"));
  // An existing directory is kept (and stays as it was).
  fs::create_directories(dir + "/kept");
  CHECK(run_admitgen("fit '" + dir + "/few.csv' --qmax 3 --smax 3 --out '" + dir + "/kept'").exit_code == 2);
  CHECK(fs::is_directory(dir + "/kept"));
}

TEST_CASE("fit cli: goodness of fit per order in fit.json, the summary table and the report") {
  const std::string dir = scratch_dir("read_goodness");
  const std::string data = sample("reference/q1s1_sigma0.01.csv");
  const auto r = run_admitgen("fit '" + data + "' --qmax 1 --smax 1 --live 40 --seed 2 --out '" + dir + "'");
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(r.output.find("rel.rms") != std::string::npos);
  const auto fit = nlohmann::json::parse(read_text(dir + "/fit.json"));
  double q1s1 = 0.0, q0s0 = 0.0;
  for (const auto& m : fit["models"]) {
    const auto& g = m["goodness_of_fit"];
    CHECK(g["estimate"] == "max_likelihood");
    if (m["order"] == "Q1S1") q1s1 = g["relative_rms_residual"].get<double>();
    if (m["order"] == "Q0S0") q0s0 = g["relative_rms_residual"].get<double>();
  }
  // Noise σ = 0.01 per component (samples/reference/README.md): the true order's residual is
  // ‖noise‖/‖D‖ ≈ σ√2/rms|D|, within the χ² spread for K = 400 (±3.5 % at 1σ) plus the slack of a
  // 40-live-point optimum; a constant (Q0S0) cannot follow the data.
  const admitgen::Measurement m = admitgen::read_measurement(data, admitgen::ReadOptions{});
  const double expected = 0.01 * std::sqrt(2.0) / std::sqrt(m.y.abs2().mean());
  CHECK(q1s1 == doctest::Approx(expected).epsilon(0.15));
  CHECK(q0s0 > 5.0 * expected);
  // The true order, noise only: no "fits poorly" (the noise does make Re y < 0 at 12 points, which is
  // reported as a note on the data, not on the fit).
  for (const auto& w : fit["warnings"]) CHECK(w.get<std::string>().find("fits poorly") == std::string::npos);
  CHECK(fit["warnings"].dump().find("not passive at 12 of 200") != std::string::npos);
  const std::string report = read_text(dir + "/report.html");
  CHECK(report.find("rel. RMS residual") != std::string::npos);
  CHECK(report.find("max |Δα|") != std::string::npos);
}

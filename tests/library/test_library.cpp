// SPDX-License-Identifier: MIT
// The material library end to end (docs/library.md): a merge equals `fit` + `emit` of each material byte for
// byte; only changed work is redone; a lost or partial unit result is redone on the next run; a bad manifest
// names file, line and value and writes nothing; unit files round-trip runs bit for bit; the band sets.
#include "test_support.hpp"

#include "codegen/band_absorption.hpp"
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "io/unit_file.hpp"
#include "library/exports.hpp"
#include "selection/fit.hpp"

#include <doctest/doctest.h>

#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace admitgen;
using namespace admitgen::test;
namespace fs = std::filesystem;

namespace {

/// Three materials of the bundled samples, copied beside the manifest (so a test may edit them), Q0-1 x
/// S0-1 (12 units) with few live points: the whole library runs in about a second.
std::string make_library(const std::string& dir, const std::string& extra_defaults = "") {
  fs::copy_file(sample("reference/q1s1_sigma0.01.csv"), dir + "/reference.csv");
  fs::copy_file(sample("synthetic/glass_beads_40mm.csv"), dir + "/beads.csv");
  fs::copy_file(sample("synthetic/mpp_three_layer.csv"), dir + "/mpp.csv");
  const std::string manifest = dir + "/walls.toml";
  write_text(manifest, "name = \"walls\"\n"
                       "[defaults]\nqmax = 1\nsmax = 1\nlive = 20\nseed = 7\nfs = [48000]\nformat = \"q31\"\n" +
                           extra_defaults +
                           "[[material]]\nname = \"reference\"\ndata = \"reference.csv\"\n"
                           "[[material]]\nname = \"beads\"\ndata = \"beads.csv\"\n"
                           "[[material]]\nname = \"mpp\"\ndata = \"mpp.csv\"\nlive = 25\n");
  return manifest;
}

std::string q(const std::string& s) { return "'" + s + "'"; }

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t p = 0; (p = text.find(what, p)) != std::string::npos; p += what.size()) ++n;
  return n;
}

/// The line of a plan listing unit `id` (empty if none).
std::string plan_line(const std::string& plan, const std::string& id) {
  const auto p = plan.find(id + " ");
  return p == std::string::npos ? std::string() : plan.substr(p, plan.find('\n', p) - p);
}

/// A unit file without its "seconds" line (the run's wall time, the one entry that differs between runs).
std::string without_seconds(std::string text) {
  const auto p = text.find("\nseconds ");
  if (p != std::string::npos) text.erase(p, text.find('\n', p + 1) - p);
  return text;
}

}  // namespace

TEST_CASE("library: the merge writes what fit and emit write, byte for byte, whatever the thread count") {
  const std::string dir = scratch_dir("library_equal");
  const std::string manifest = make_library(dir);
  for (const char* threads : {"1", "2"}) {
    const std::string out = dir + "/lib" + threads;
    REQUIRE(run_admitgen("library plan " + q(manifest) + " --out " + q(out)).exit_code == 0);
    const auto ran = run_admitgen(std::string("library run -j ") + threads + " " + q(out));
    REQUIRE(ran.exit_code == 0);
    CHECK(ran.output.find("ran 12 of 12 units") != std::string::npos);
    const auto merged = run_admitgen("library merge " + q(out));
    REQUIRE_MESSAGE(merged.exit_code == 0, merged.output);
  }
  // Each material by hand, in the manifest's folder (fit.json records the data path as the manifest writes it).
  struct Plain {
    const char* name;
    const char* data;
    const char* live;
  };
  const auto cwd = fs::current_path();
  for (const Plain& p : {Plain{"reference", "reference.csv", "20"}, Plain{"beads", "beads.csv", "20"}, Plain{"mpp", "mpp.csv", "25"}}) {
    const std::string plain = dir + "/plain_" + p.name;
    fs::current_path(dir);
    const auto fit = run_admitgen(std::string("fit ") + p.data + " --qmax 1 --smax 1 --live " + p.live +
                                  " --seed 7 -q --out " + q(plain));
    fs::current_path(cwd);
    REQUIRE_MESSAGE(fit.exit_code == 0, fit.output);
    REQUIRE(run_admitgen("emit " + q(plain + "/fit.json") + " --fs 48000 --format q31 --name walls_" + p.name +
                         " -q --out " + q(plain + "/" + p.name + ".h"))
                .exit_code == 0);
    for (const std::string& file : std::vector<std::string>{"fit.json", "posterior.json", "predictive.csv",
                                                            "posterior_Q1S1.csv", "report.html", std::string(p.name) + ".h"}) {
      CAPTURE(p.name);
      CAPTURE(file);
      const std::string expected = read_text(plain + "/" + file);
      REQUIRE(!expected.empty());
      CHECK(read_text(dir + "/lib1/materials/" + p.name + "/" + file) == expected);
      CHECK(read_text(dir + "/lib2/materials/" + p.name + "/" + file) == expected);
    }
    // The library header holds the material's header verbatim, and its table points at its model.
    const std::string library_header = read_text(dir + "/lib1/walls.h");
    CHECK(library_header.find(read_text(plain + "/" + p.name + ".h")) != std::string::npos);
    CHECK(library_header.find(std::string("{&walls_") + p.name + "_48000}") != std::string::npos);
  }
  for (const char* file : {"walls.h", "bands.json", "bands.csv", "report.html"})
    CHECK(read_text(dir + "/lib1/" + file) == read_text(dir + "/lib2/" + file));
}

TEST_CASE("library: editing one data file re-runs only that material's units, emit settings none") {
  const std::string dir = scratch_dir("library_incremental");
  const std::string manifest = make_library(dir);
  const std::string out = dir + "/lib";
  REQUIRE(run_admitgen("library plan -q " + q(manifest) + " --out " + q(out)).exit_code == 0);
  REQUIRE(run_admitgen("library run " + q(out)).exit_code == 0);
  const std::string before = read_text(out + "/units/reference/Q0S1.unit");
  CHECK(run_admitgen("library plan " + q(manifest) + " --out " + q(out)).output.find("12 up to date, 0 to run") !=
        std::string::npos);

  // One value of the beads data changed (last digit of the first data row).
  std::string beads = read_text(dir + "/beads.csv");
  const auto row = beads.find("\n1");  // the first line starting with a digit after the comments
  REQUIRE(row != std::string::npos);
  const auto end = beads.find('\n', row + 1);
  beads[end - 1] = beads[end - 1] == '1' ? '2' : '1';
  write_text(dir + "/beads.csv", beads);
  const auto plan = run_admitgen("library plan " + q(manifest) + " --out " + q(out));
  CHECK(plan.output.find("8 up to date, 4 to run") != std::string::npos);
  CHECK(count(plan.output, "to-run") == 4);
  for (const char* order : {"Q0S0", "Q0S1", "Q1S0", "Q1S1"})
    CHECK(plan_line(plan.output, std::string("beads/") + order).find(" to-run ") != std::string::npos);
  const auto ran = run_admitgen("library run " + q(out));
  CHECK(ran.output.find("ran 4 of 12 units") != std::string::npos);
  CHECK(read_text(out + "/units/reference/Q0S1.unit") == before);

  // Emit settings and the merge-only fit settings (grid, selection) re-run no unit.
  write_text(manifest, read_text(manifest) + "\n");
  std::string m = read_text(manifest);
  m.replace(m.find("fs = [48000]"), 12,
            "fs = [48000, 96000]\nselect = \"cheapest:10\"\ntarget-alpha = 0.02\ntarget-rms = 0.05\nmax-buffers = 6");
  write_text(manifest, m);
  CHECK(run_admitgen("library plan " + q(manifest) + " --out " + q(out)).output.find("12 up to date, 0 to run") !=
        std::string::npos);
  // A sampling setting of one material re-runs that material only.
  m.replace(m.find("live = 25"), 9, "live = 30");
  write_text(manifest, m);
  CHECK(run_admitgen("library plan " + q(manifest) + " --out " + q(out)).output.find("8 up to date, 4 to run") !=
        std::string::npos);
}

TEST_CASE("library: a lost or partial unit result is redone by the next run, the others are kept") {
  const std::string dir = scratch_dir("library_resume");
  const std::string manifest = make_library(dir);
  const std::string out = dir + "/lib";
  REQUIRE(run_admitgen("library plan -q " + q(manifest) + " --out " + q(out)).exit_code == 0);
  REQUIRE(run_admitgen("library run " + q(out)).exit_code == 0);
  REQUIRE(run_admitgen("library merge -q " + q(out)).exit_code == 0);
  const std::string header = read_text(out + "/walls.h"), fit = read_text(out + "/materials/mpp/fit.json");
  const std::string lost = out + "/units/mpp/Q1S1.unit", partial = out + "/units/beads/Q0S1.unit";
  const std::string partial_text = read_text(partial);
  fs::remove(lost);
  write_text(partial, partial_text.substr(0, partial_text.size() / 2));  // a write cut short (not atomic)
  const auto merge = run_admitgen("library merge -q " + q(out));
  CHECK(merge.exit_code == 2);
  CHECK(merge.output.find("2 of 12 units have no current result") != std::string::npos);
  CHECK(run_admitgen("library run " + q(out)).output.find("ran 2 of 12 units") != std::string::npos);
  CHECK(without_seconds(read_text(partial)) == without_seconds(partial_text));  // the same run, but its run time
  REQUIRE(run_admitgen("library merge -q " + q(out)).exit_code == 0);
  CHECK(read_text(out + "/walls.h") == header);
  CHECK(read_text(out + "/materials/mpp/fit.json") == fit);
}

TEST_CASE("library: a bad manifest exits 2 naming file, line and value, and writes nothing") {
  const std::string dir = scratch_dir("library_bad");
  const std::string good = read_text(make_library(dir));
  struct Bad {
    const char* name;
    const char* from;  ///< text of the good manifest to replace
    const char* to;
    const char* expect;  ///< in the message, after "walls.toml:"
  };
  const std::vector<Bad> cases{
      {"live out of range", "live = 25", "live = 5", "18: material mpp: live: --live: Value 5 not in range"},
      {"unknown key", "live = 25", "lives = 25", "18: unknown key 'lives'"},
      {"bad column spec", "live = 25", "columns = \"f,re\"", "18: material mpp: columns:"},
      {"threads", "live = 25", "threads = 2", "18: 'threads' cannot be set in a manifest"},
      {"missing data file", "data = \"mpp.csv\"", "data = \"nope.csv\"", "17: material mpp: no such data file"},
      {"duplicate name", "name = \"mpp\"", "name = \"beads\"", "16: a second material of this name (value 'beads')"},
      {"bad name", "name = \"mpp\"", "name = \"m p\"", "16: a material's name may hold only letters, digits and _"},
      {"not TOML", "live = 25", "live = = 25", "18: not TOML"},
      {"bad format", "format = \"q31\"", "format = \"q7\"", "8: material reference: format:"},
      {"prior file missing", "live = 25", "priors = \"none.json\"", "18: material mpp: priors:"},
  };
  for (const Bad& b : cases) {
    CAPTURE(b.name);
    std::string text = good;
    REQUIRE(text.find(b.from) != std::string::npos);
    text.replace(text.find(b.from), std::strlen(b.from), b.to);
    write_text(dir + "/walls.toml", text);
    const std::string out = dir + "/out";
    const auto r = run_admitgen("library plan " + q(dir + "/walls.toml") + " --out " + q(out));
    CHECK(r.exit_code == 2);
    CHECK_MESSAGE(r.output.find("walls.toml:" + std::string(b.expect)) != std::string::npos, r.output);
    CHECK(!fs::exists(out));
  }
}

TEST_CASE("library: a unit file reads back the run bit for bit") {
  const Measurement data = read_measurement(sample("reference/q1s1_sigma0.01.csv"), {});
  FitSettings settings;
  settings.sampler.live = 20;
  settings.sampler.seed = 3;
  io::UnitResult unit{"k", fit_order(data, Order(1, 1), settings)};
  const std::string text = io::unit_text(unit);
  const std::string path = scratch_dir("library_unit") + "/Q1S1.unit";
  write_text(path, text);
  const io::UnitResult back = io::read_unit_file(path);
  const NestedRun &a = unit.model.run, &b = back.model.run;
  REQUIRE(a.size() > 0);
  CHECK(b.samples.size() == a.samples.size());
  CHECK(std::memcmp(a.samples.data(), b.samples.data(), a.samples.size() * sizeof(double)) == 0);
  CHECK(std::memcmp(a.log_likelihood.data(), b.log_likelihood.data(), a.size() * sizeof(double)) == 0);
  CHECK(std::memcmp(a.log_weight.data(), b.log_weight.data(), a.size() * sizeof(double)) == 0);
  CHECK(std::memcmp(&a.log_z, &b.log_z, sizeof(double)) == 0);
  CHECK(b.calls == a.calls);
  CHECK(back.model.parameters.size() == unit.model.parameters.size());
  CHECK(back.model.parameters[1].mean == unit.model.parameters[1].mean);  // recomputed from the same run
  CHECK(io::unit_text(back) == text);
  CHECK(io::unit_file_key(path) == "k");
  write_text(path, text.substr(0, text.size() - 2));  // cut short: not a whole unit file
  CHECK(io::unit_file_key(path).empty());
  CHECK_THROWS_WITH_AS(io::read_unit_file(path), doctest::Contains("Q1S1.unit:"), InputError);
}

TEST_CASE("library: band sets of a frequency-independent admittance are its absorption in every band") {
  // G = 0.5 at every frequency (order Q0S0): R = (1 - G)/(1 + G) = 1/3, alpha_0 = 1 - 1/9 = 8/9 in every band.
  // The band value is a mean of 32 equal terms, each rounded: 32 ulp bound the difference.
  Eigen::VectorXd theta(1);
  theta << 0.5;
  const double expected = 8.0 / 9.0, tolerance = 32 * std::numeric_limits<double>::epsilon();
  const auto steam = codegen::band_absorption(Order(0, 0), theta, library::steam_audio_bands(), 100.0, 10000.0);
  REQUIRE(steam.size() == 3);
  CHECK(steam[0].center_hz == 400.0);
  CHECK(steam[1].center_hz == 2500.0);
  CHECK(steam[2].center_hz == 15000.0);
  CHECK(steam[0].hi_hz == 800.0);  // Steam Audio: low up to 800 Hz, mid 800 Hz - 8 kHz, high above 8 kHz
  CHECK(steam[1].hi_hz == 8000.0);
  CHECK(steam[0].in_data);
  CHECK(!steam[2].in_data);  // 8-20 kHz lies above the data's 10 kHz
  const auto four = codegen::band_absorption(Order(0, 0), theta, library::four_bands(), 100.0, 10000.0);
  REQUIRE(four.size() == 4);
  for (const auto& set : {steam, four})
    for (const auto& b : set) {
      CHECK(b.alpha_normal == doctest::Approx(expected).epsilon(tolerance));
      CHECK(b.lo_hz < b.center_hz);
      CHECK(b.center_hz < b.hi_hz);
    }
  // The octave bands through the same definition as before (IEC centres 31.5 Hz ... 16 kHz).
  const auto octave = codegen::band_absorption(Order(0, 0), theta, 1, 100.0, 10000.0);
  REQUIRE(octave.size() == 10);
  CHECK(octave.front().center_hz == doctest::Approx(31.6227766).epsilon(1e-9));
  CHECK(octave.back().alpha_normal == doctest::Approx(expected).epsilon(tolerance));
}

// SPDX-License-Identifier: MIT
// Library errors name the setting at fault by its settings field (core/errors.hpp, setting()); the CLI
// respells each as its flag (cli/options.hpp, flag_for). References: the field and flag names as the
// settings structs and the option groups spell them.
#include "cli/check_command.hpp"
#include "cli/diagnose_command.hpp"
#include "cli/emit_command.hpp"
#include "cli/fit_command.hpp"
#include "cli/options.hpp"
#include "cli/synth_command.hpp"
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace admitgen;

TEST_CASE("setting errors: the library names the field, the CLI spells the flag") {
  ReadOptions options;
  options.rho_c = -1.0;
  const std::string path = test::scratch_dir("setting_errors") + "/y.csv";
  test::write_text(path, "f,re,im\n100,0.5,0.1\n200,0.5,0.1\n");
  try {
    read_measurement(path, options);
    FAIL("a negative rho_c was accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "rho_c must be a positive number, got -1");
    CHECK(e.settings() == std::vector<std::string>{"rho_c"});
    CHECK(e.spelled(cli::flag_for) == "--rho-c must be a positive number, got -1");
  }
  const InputError plain("no setting named here");
  CHECK(plain.settings().empty());
  CHECK(plain.spelled(cli::flag_for) == "no setting named here");
  const FileError located("data.csv", 3, setting("phase") + " deg, but the file gives the phase in radians", "1.2");
  CHECK(std::string(located.what()) == "data.csv:3: phase deg, but the file gives the phase in radians (value '1.2')");
  CHECK(located.spelled(cli::flag_for) == "data.csv:3: --phase-unit deg, but the file gives the phase in radians (value '1.2')");
}

TEST_CASE("setting text: warnings and advice name settings with values, files read keys, the CLI reads flags") {
  const std::string text = "read as " + setting("quantity", "impedance") + " " + setting("rho_c", "413.3") +
                           ", or drop " + setting("enforce_passivity = false");
  CHECK(plain_settings(text) == "read as quantity=impedance rho_c=413.3, or drop enforce_passivity = false");
  CHECK(cli::spelled(text) == "read as --quantity impedance --rho-c 413.3, or drop --no-passivity-enforcement");
  CHECK(named_settings(text) == std::vector<std::string>{"quantity", "rho_c", "enforce_passivity = false"});
  CHECK(cli::spelled("no setting named here") == "no setting named here");
  const InputError e(setting("fs_hz", "8000") + " Hz: too low; raise " + setting("fs_hz"));
  CHECK(std::string(e.what()) == "fs_hz=8000 Hz: too low; raise fs_hz");
  CHECK(e.spelled(cli::flag_for) == "--fs 8000 Hz: too low; raise --fs");
}

TEST_CASE("setting errors: every setting a library message names has a flag") {
  // Scans generator/ (outside cli/) for setting("KEY") and checks that the CLI spells each KEY as a flag.
  const std::filesystem::path generator = std::filesystem::path(test::sample("")).parent_path().parent_path() / "generator";
  REQUIRE(std::filesystem::is_directory(generator));
  const std::regex call(R"re(setting\("([^"]+)"[,)])re");
  std::set<std::string> keys;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(generator)) {
    if (entry.path().extension() != ".cpp" || entry.path().parent_path().filename() == "cli") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (std::sregex_iterator it(s.begin(), s.end(), call), end; it != end; ++it) keys.insert((*it)[1].str());
  }
  CHECK(keys.size() >= 25);  // the data, tube, fit, emit and synthesis settings named today
  // The flag must be an option of some subcommand of the real command line.
  CLI::App app;
  int exit_code = 0;
  cli::setup_fit_command(app, exit_code);
  cli::setup_emit_command(app, exit_code);
  cli::setup_synth_command(app, exit_code);
  cli::setup_diagnose_command(app, exit_code);
  cli::setup_check_command(app, exit_code);
  for (const auto& key : keys) {
    INFO(key);
    const std::string flag = cli::flag_for(key);
    REQUIRE(flag.rfind("--", 0) == 0);
    bool found = false;
    for (const char* name : {"fit", "emit", "synth", "diagnose", "check"})
      found = found || app.get_subcommand(name)->get_option_no_throw(flag) != nullptr;
    CHECK(found);
  }
}

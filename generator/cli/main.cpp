// SPDX-License-Identifier: MIT
/// @file
/// admitgen command line: one options struct + setup + run function per subcommand (cli/*_command.*).
/// Only this function maps errors to exit codes: 0 success, 1 a check found a violation, 2 bad input.
#include "cli/check_command.hpp"
#include "cli/diagnose_command.hpp"
#include "cli/emit_command.hpp"
#include "cli/fit_command.hpp"
#include "cli/library_command.hpp"
#include "cli/options.hpp"
#include "cli/synth_command.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  CLI::App app{"admitgen: Bayesian multipole admittance fits and causal C boundary filters"};
  app.set_version_flag("--version", admitgen::kVersion);
  app.require_subcommand(1);
  int exit_code = 0;
  admitgen::cli::setup_fit_command(app, exit_code);
  admitgen::cli::setup_emit_command(app, exit_code);
  admitgen::cli::setup_synth_command(app, exit_code);
  admitgen::cli::setup_diagnose_command(app, exit_code);
  admitgen::cli::setup_check_command(app, exit_code);
  admitgen::cli::setup_library_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "admitgen: error: {}\nRun with --help for usage.\n", e.what());
    return 2;
  } catch (const admitgen::UnsafeModelError& e) {
    fmt::print(stderr, "admitgen: error: {}\n", e.spelled(admitgen::cli::flag_for));
    return 1;  // read, and unsafe: a check fails (the same exit code as admitgen check)
  } catch (const admitgen::InputError& e) {
    // A library error names the setting at fault by its field; the user gave it as a flag.
    fmt::print(stderr, "admitgen: error: {}\n", e.spelled(admitgen::cli::flag_for));
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "admitgen: internal error: {}\n", e.what());
    return 3;
  }
  return exit_code;
}

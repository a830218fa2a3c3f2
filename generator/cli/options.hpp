// SPDX-License-Identifier: MIT
/// @file
/// What the subcommands share: options bound straight to the fields of the library's settings structs
/// (their defaults are the structs'), the two option groups more than one subcommand takes (reading
/// measured data; the impedance-tube geometry), and the flag that spells each setting a library error
/// names (core/errors.hpp, setting()). docs/reading-data.md is the reference of the data options.
#pragma once

#include "data/read_options.hpp"
#include "physics/synthetic_measurement.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace admitgen::cli {

/// An option whose text a library parser turns into the field's value (the parser throws InputError).
template <class T, class Parse>
CLI::Option* add_parsed_option(CLI::App& app, const std::string& name, T& field, Parse parse, const std::string& help) {
  return app.add_option_function<std::string>(
      name, [&field, parse](const std::string& text) { field = parse(text); }, help);
}

/// A flag that sets a boolean setting to false ("--no-...").
CLI::Option* add_clearing_flag(CLI::App& app, const std::string& name, bool& field, const std::string& help);

/// Where a set of data options lives: prefix "" gives --columns, --band, ...; prefix "sim-" gives
/// --sim-columns, --sim-band, ... (diagnose reads its --sim table with them); group titles them in --help.
struct DataOptionScope {
  std::string prefix;
  std::string group;
};

/// Reading measured data (fit, diagnose): layout (--delimiter, --decimal, --skip-rows), columns
/// (--columns), quantity and units (--quantity, --normalized / --rho-c, --magnitude, --phase-unit,
/// --time-convention), --band and --no-plausibility-errors, each with scope.prefix after "--".
void add_data_options(CLI::App& app, ReadOptions& read, const DataOptionScope& scope = {});

/// base, with every field whose option "--PREFIX..." was given on app's command line taken from given
/// (the options add_data_options(app, given, {PREFIX}) filled): a second file read like the first
/// except where its own options say otherwise.
ReadOptions with_given_options(const CLI::App& app, const std::string& prefix, const ReadOptions& base,
                               const ReadOptions& given);

/// The impedance tube (synth, diagnose): --tube-diameter, --mic-spacing, --mic-distance, --temperature.
void add_tube_options(CLI::App& app, TubeSetup& tube);

/// The command-line spelling of a setting named by a library error ("rho_c" -> "--rho-c"); an unknown
/// key is returned as it is.
std::string flag_for(const std::string& setting_key);

}  // namespace admitgen::cli

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
#include <vector>

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

/// The data options add_data_options registered, each with the ReadOptions field it sets.
class DataOptions {
 public:
  using Take = void (*)(const ReadOptions& from, ReadOptions& to);
  /// base, with every field whose option was given on the command line taken from given (the ReadOptions
  /// these options filled): a second file read like the first except where its own options say otherwise.
  /// Call after parsing.
  ReadOptions take_given(const ReadOptions& base, const ReadOptions& given) const;

 private:
  struct Bound {
    CLI::Option* option;
    Take take;
  };
  std::vector<Bound> bound_;
  friend DataOptions add_data_options(CLI::App& app, ReadOptions& read, const DataOptionScope& scope);
};

/// Reading measured data (fit, diagnose): layout (--delimiter, --decimal, --skip-rows), columns
/// (--columns), quantity and units (--quantity, --normalized / --rho-c, --magnitude, --phase-unit,
/// --time-convention), --band and --no-plausibility-errors, each with scope.prefix after "--".
DataOptions add_data_options(CLI::App& app, ReadOptions& read, const DataOptionScope& scope = {});

/// The impedance tube (synth, diagnose): --tube-diameter, --mic-spacing, --mic-distance, --temperature.
void add_tube_options(CLI::App& app, TubeSetup& tube);

/// The command-line spelling of a setting named by library text ("rho_c" -> "--rho-c"); an unknown
/// key is returned as it is. The one table from settings to flags.
std::string flag_for(const std::string& setting_key);

/// Library text (a warning, a note, a refusal) as the command line prints it: each setting it names
/// (core/errors.hpp, setting()) spelled as its flag, a value after it ("--quantity impedance").
std::string spelled(const std::string& text);

}  // namespace admitgen::cli

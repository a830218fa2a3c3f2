// SPDX-License-Identifier: MIT
/// @file
/// The data-reading options shared by every subcommand that reads measured data (fit, diagnose):
/// layout (--delimiter, --decimal, --skip-rows), columns (--columns), quantity and units
/// (--quantity, --normalized / --rho-c, --magnitude, --phase-unit, --time-convention), --band and
/// --no-plausibility-errors. Bound while parsing, converted to ReadOptions (validated) when the
/// command runs. docs/reading-data.md is the reference.
#pragma once

#include "data/read_options.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace admitgen::cli {

struct DataOptions {
  std::optional<std::string> columns;
  std::optional<std::string> quantity;
  bool normalized = false;
  std::optional<double> rho_c;
  std::optional<std::string> band;
  std::string delimiter = "auto";
  std::string decimal = "auto";
  int skip_rows = 0;
  std::optional<std::string> magnitude;
  std::optional<std::string> phase_unit;
  std::optional<std::string> time_convention;
  bool no_plausibility_errors = false;

  /// Throws InputError on any inconsistent or malformed option.
  ReadOptions to_read_options() const;
};

void add_data_options(CLI::App& app, DataOptions& options);

}  // namespace admitgen::cli

/// @file
/// The data-reading options shared by every subcommand that reads measured data (fit, diagnose):
/// --columns, --quantity, --normalized / --rho-c, --band. Bound while parsing, converted to
/// ReadOptions (validated) when the command runs.
#pragma once

#include "data/read_options.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace admitgen::cli {

struct DataOptions {
  std::string columns = "f,re,im";
  std::string quantity = "admittance";
  bool normalized = false;
  std::optional<double> rho_c;
  std::optional<std::string> band;

  /// Throws InputError on any inconsistent or malformed option.
  ReadOptions to_read_options() const;
};

void add_data_options(CLI::App& app, DataOptions& options);

}  // namespace admitgen::cli

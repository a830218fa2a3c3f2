// SPDX-License-Identifier: MIT
/// @file
/// `admitgen fit DATA --out DIR ...`: evidence of every order of the grid, selection, parameter
/// summaries; writes DIR/fit.json and prints a summary table.
#pragma once

#include "data/read_options.hpp"
#include "selection/fit.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace admitgen::cli {

/// What `fit` was asked: the files, and the library's settings, which the options fill directly.
struct FitCommand {
  std::string data;
  std::string out;
  ReadOptions read;
  FitSettings settings;
  bool quiet = false;
  bool cost_only = false;
};

void setup_fit_command(CLI::App& app, int& exit_code);
/// Binds the reading options and the fit settings of `fit` (not its files nor --quiet/--cost-only):
/// `fit` and the library manifest (library_command.hpp) read the same options through it.
void add_fit_options(CLI::App& app, ReadOptions& read, FitSettings& settings);
int run_fit_command(const FitCommand& command);

}  // namespace admitgen::cli

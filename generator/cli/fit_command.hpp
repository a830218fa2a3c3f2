// SPDX-License-Identifier: MIT
/// @file
/// `admitgen fit DATA --out DIR ...`: evidence of every order of the grid, selection, parameter
/// summaries; writes DIR/fit.json and prints a summary table.
#pragma once

#include "cli/data_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace admitgen::cli {

struct FitOptions {
  std::string data;
  std::string out;
  DataOptions read;
  int qmax = 3;
  int smax = 3;
  int live = 500;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string select = "best";
  std::string priors;
  std::string likelihood_k = "2N";
  double dlogz = 0.01;
  long max_iterations = 1'000'000;
  int slices = 0;
  int missed_mode_retries = 2;
  bool no_symmetry_reduction = false;
  bool passive = false;
  std::string sampler = "full";  ///< full | poles (residues integrated analytically)
  bool quiet = false;
  bool cost_only = false;
};

void setup_fit_command(CLI::App& app, int& exit_code);
int run_fit_command(const FitOptions& options);

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
/// @file
/// Helpers shared by the tests: paths to the built CLI and the bundled samples, running the CLI in a
/// child process with captured output, and scratch directories.
#pragma once

#include "core/rng.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen::test {

struct CommandResult {
  int exit_code;
  std::string output;  ///< stdout and stderr together
};

/// Runs `admitgen ARGS` (ARGS already shell-quoted where needed) and captures its output.
CommandResult run_admitgen(const std::string& args);

/// A fresh empty directory under the build tree's scratch area (removed first if present).
std::string scratch_dir(const std::string& name);

/// Path of a bundled sample, e.g. sample("reference/q1s1_sigma0.01.csv").
std::string sample(const std::string& relative);

/// Writes text to a file (test fixtures).
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);

/// Repeated evidence runs (one per seed): the mean ln Z, its sample standard deviation (n − 1) and the
/// mean of the errors the runs reported; an honest error estimate has spread ≈ reported.
struct SeedScatter {
  double mean = 0.0, spread = 0.0, reported = 0.0;
};
SeedScatter seed_scatter(const std::vector<double>& log_z, const std::vector<double>& log_z_error);

/// An r × c matrix of independent uniform draws in [−1, 1).
Eigen::MatrixXd random_matrix(Rng& rng, Eigen::Index r, Eigen::Index c);

}  // namespace admitgen::test

// SPDX-License-Identifier: MIT
/// @file
/// `admitgen check FILE.h|FIT.json [--json]`: proves an emitted filter (or a fit's continuous model)
/// causal, stable, passive, free of overflow and limit cycles (checks/check_suite.hpp). Exit 0 when
/// every check holds, 1 when one fails (each failure named), 2 on unusable input.
#pragma once

#include "codegen/fidelity.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace admitgen::cli {

struct CheckOptions {
  std::string file;
  bool json = false;
  std::string order;              ///< fits only: check this order instead of the selected one
  std::string estimate = "passive";  ///< fits only: posterior summary taken as the parameters
  double fidelity_tolerance = codegen::kDefaultFidelityTolerance;  ///< headers only (checks::CheckSubject)
};

void setup_check_command(CLI::App& app, int& exit_code);
int run_check_command(const CheckOptions& options);

}  // namespace admitgen::cli

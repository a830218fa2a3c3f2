// SPDX-License-Identifier: MIT
/// @file
/// `admitgen emit FIT.json --fs HZ [--fs HZ ...] --format f32|q31|q15 [--name IDENT] --out FILE.h`:
/// the causal C header of the fit's model for the C99 runtime (codegen/emission.hpp), optionally the
/// band-absorption JSON and bit-exact golden vectors.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace admitgen::cli {

struct EmitOptions {
  std::string fit;
  std::vector<double> fs_hz;
  std::string format;
  std::string name;  ///< default: the output file's stem, made a C identifier
  std::string out;
  std::string order;
  std::string estimate = "passive";
  int fir_taps = 0;
  std::string bands_json;
  std::string golden;
  std::uint64_t golden_seed = 1;
  std::string templates;
  bool quiet = false;
  bool no_passivity_enforcement = false;  ///< emit the estimate as fitted, plain least-squares refit
  bool allow_unsafe = false;  ///< write the header even if `admitgen check` would fail it (warns per failure)
};

void setup_emit_command(CLI::App& app, int& exit_code);
int run_emit_command(const EmitOptions& options);

}  // namespace admitgen::cli

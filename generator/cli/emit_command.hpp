// SPDX-License-Identifier: MIT
/// @file
/// `admitgen emit FIT.json --fs HZ [--fs HZ ...] --format f32|q31|q15 [--name IDENT] --out FILE.h`:
/// the causal C header of the fit's model for the C99 runtime (codegen/emission.hpp), optionally the
/// band-absorption JSON and bit-exact golden vectors.
#pragma once

#include "codegen/emission.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace admitgen::cli {

/// What `emit` was asked: the files, the header's settings (filled by the options directly), and what
/// to do with a header that fails `admitgen check`.
struct EmitCommand {
  std::string fit;
  std::string out;
  codegen::EmitSettings settings;  ///< an empty name: the output file's stem, made a C identifier
  std::string bands_json;
  std::string golden;
  std::uint64_t golden_seed = 1;
  std::string templates;
  bool quiet = false;
  bool allow_unsafe = false;  ///< write the header even if `admitgen check` would fail it (warns per failure)
};

void setup_emit_command(CLI::App& app, int& exit_code);
/// Binds the header settings of `emit` (not its files): `emit` and the library manifest read the same options.
void add_emit_options(CLI::App& app, codegen::EmitSettings& settings);
int run_emit_command(const EmitCommand& command);

}  // namespace admitgen::cli

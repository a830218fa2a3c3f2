// SPDX-License-Identifier: MIT
/// @file
/// `admitgen library plan|run|unit|merge|slurm`: a material library described by a manifest
/// (cli/library_manifest.hpp), fitted locally or on Slurm, merged into each material's fit.json and
/// header and the library's exports (docs/library.md).
#pragma once

#include <CLI/CLI.hpp>

namespace admitgen::cli {

void setup_library_command(CLI::App& app, int& exit_code);

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
/// @file
/// `admitgen synth --material SPEC --out DATA.csv [--effect NAME:k=v,...]... [--noise STD] [--seed N]
/// [--band FMIN:FMAX] [--points N] [--tube-diameter M --mic-spacing M --mic-distance M] [--temperature C]`:
/// synthetic "measured" admittance from a physical material (physics/material_spec.hpp) through the
/// named measurement effects (physics/effects.hpp), written as a CSV that `fit` reads without options.
#pragma once

#include "physics/synthetic_measurement.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace admitgen::cli {

/// What `synth` was asked: the material and effects as written (they are stamped into the CSV), the
/// frequency grid, and the library's request, which the other options fill directly.
struct SynthCommand {
  std::string material;
  std::string out;
  std::vector<std::string> effects;
  std::string band = "100:4000";  ///< default grid: 200 log-spaced points 100-4000 Hz (the paper's band)
  int points = 200;
  SynthesisRequest request;  ///< noise_std, seed, tube; material, effects and f_hz are set when it runs
  bool quiet = false;
};

void setup_synth_command(CLI::App& app, int& exit_code);
int run_synth_command(const SynthCommand& command);

}  // namespace admitgen::cli

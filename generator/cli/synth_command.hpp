// SPDX-License-Identifier: MIT
/// @file
/// `admitgen synth --material SPEC --out DATA.csv [--effect NAME:k=v,...]... [--noise STD] [--seed N]
/// [--band FMIN:FMAX] [--points N] [--tube-diameter M --mic-spacing M --mic-distance M] [--temperature C]`:
/// synthetic "measured" admittance from a physical material (physics/material_spec.hpp) through the
/// named measurement effects (physics/effects.hpp), written as a CSV that `fit` reads without options.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace admitgen::cli {

struct SynthOptions {
  std::string material;
  std::string out;
  std::vector<std::string> effects;
  double noise = 0.0;
  std::uint64_t seed = 1;
  std::string band = "100:4000";  ///< default grid: 200 log-spaced points 100-4000 Hz (the paper's band)
  int points = 200;
  std::optional<double> tube_diameter;
  std::optional<double> mic_spacing;
  std::optional<double> mic_distance;
  double temperature = 20.0;
  bool quiet = false;
};

void setup_synth_command(CLI::App& app, int& exit_code);
int run_synth_command(const SynthOptions& options);

}  // namespace admitgen::cli

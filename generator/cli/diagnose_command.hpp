// SPDX-License-Identifier: MIT
/// @file
/// `admitgen diagnose --real DATA.csv (--sim SIM.csv | --sim SPEC | --fit FIT.json) --out DIR
/// [--fs HZ --format q31] [--tube-diameter M --mic-spacing M --mic-distance M] [--temperature C]`:
/// where the sim-to-real gap lies, which pipeline stage adds it, which unmodelled effect causes it
/// and how far it shrinks (diagnosis/diagnosis.hpp). Writes DIR/diagnosis.json and prints a summary.
/// Without --sim and --fit (or with --reference passive) the reference is the closest passive causal wall
/// (diagnosis/passive_reference.hpp): DIR/passive_diagnosis.json, and --write-corrected FILE the corrected data.
/// Exit 0 when the verdict is `none`, 1 when it names an effect (a gap with an identified cause;
/// diagnosis.json is written in both cases), 2 on bad input (nothing written).
#pragma once

#include "data/read_options.hpp"
#include "diagnosis/effect_identification.hpp"
#include "physics/synthetic_measurement.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace admitgen::cli {

/// What `diagnose` was asked: the two sides, the pipeline stages, and the library's settings (reading,
/// tube, effect identification), which the options fill directly.
struct DiagnoseCommand {
  std::string real;
  std::optional<std::string> sim;  ///< a CSV path if such a file exists, else a material SPEC
  std::optional<std::string> fit;
  std::string out;
  std::string reference = "sim";  ///< "passive": physics is the reference (implied with neither --sim nor --fit)
  std::optional<std::string> write_corrected;  ///< passive reference: the corrected data as CSV for `fit`
  std::optional<double> fs;
  std::string format = "q31";
  bool format_given = false;
  ReadOptions read;      ///< --real, and a --sim CSV except where a --sim-* data option says otherwise
  ReadOptions sim_given;  ///< what the --sim-* data options set (DataOptions::take_given merges them)
  ReadOptions sim_read;   ///< how a --sim CSV is read: read with the given --sim-* options
  TubeSetup tube;
  diagnosis::IdentificationSettings settings;  ///< sampler (--live, --dlogz, --seed) and --threads
  bool quiet = false;
};

void setup_diagnose_command(CLI::App& app, int& exit_code);
int run_diagnose_command(const DiagnoseCommand& command);

}  // namespace admitgen::cli

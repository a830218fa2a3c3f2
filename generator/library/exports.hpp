// SPDX-License-Identifier: MIT
/// @file
/// What a merged library hands an engine (docs/library.md, "Outputs"): one C header with every material
/// (each material's header exactly as `admitgen emit` writes it, then an enum of the materials and a table of
/// their runtime models per rate), the band absorption of every material as JSON and CSV (octave, one-third
/// octave, Steam Audio's three bands and a four-band set), and one HTML page comparing the materials.
#pragma once

#include "codegen/band_absorption.hpp"
#include "codegen/emission.hpp"
#include "selection/fit.hpp"

#include <string>
#include <vector>

namespace admitgen::library {

/// One merged material: its emission and header (as emit wrote them) and its selected model.
struct MaterialOutput {
  std::string name;
  codegen::Emission emission;
  std::string header;
  ModelResult selected{Order(0, 0), {}, 0, 0.0, {}};
  std::vector<std::string> warnings;
};

/// Steam Audio's three material bands (docs/library.md, "Band sets"): centres 400 Hz, 2.5 kHz, 15 kHz;
/// edges 800 Hz and 8 kHz as Steam Audio states them, outer edges 200 Hz and 20 kHz.
std::vector<codegen::BandEdges> steam_audio_bands();
/// Four two-octave bands centred at 250 Hz, 1 kHz, 4 kHz and 16 kHz (edges 125 Hz … 20 kHz).
std::vector<codegen::BandEdges> four_bands();

/// The library header: the materials' headers, then the enum NAME_material, NAME_rates, NAME_names and the
/// table NAME_models[material][rate] (all materials share one format and one rate list; the manifest reader
/// ensures it).
std::string library_header(const std::string& name, const std::vector<MaterialOutput>& materials);
/// One self-contained HTML page: every material's absorption and fit quality side by side.
std::string library_report(const std::string& name, const std::vector<MaterialOutput>& materials);

/// Writes DIR/NAME.h, DIR/bands.json, DIR/bands.csv and DIR/report.html (each atomically).
void write_library_files(const std::string& name, const std::string& dir, const std::vector<MaterialOutput>& materials);

}  // namespace admitgen::library

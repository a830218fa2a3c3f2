// SPDX-License-Identifier: MIT
/// @file
/// The band-absorption file of `admitgen emit --bands-json` (docs/formats.md, "Band absorption"), schema
/// "admitgen.bands/1": octave and one-third-octave absorption, normal and random incidence, of the
/// emitted model. Its one writer (nothing reads it back).
#pragma once

#include "codegen/emission.hpp"

#include <string>
#include <utility>
#include <vector>

namespace admitgen::io {

/// The file's text: JSON indented by 2, then a newline.
std::string bands_text(const codegen::Emission& emission);

/// One material of a library's band files (docs/library.md, "Outputs"): its band sets by name, in order.
struct MaterialBands {
  std::string material, order, input_sha256;
  std::vector<std::pair<std::string, std::vector<codegen::BandAbsorption>>> sets;
};

/// A library's band file, schema "admitgen.library-bands/1": JSON indented by 2, then a newline.
std::string library_bands_text(const std::string& library, const std::vector<MaterialBands>& materials);
/// The same numbers as CSV, one row per material and band (shortest round-trip numbers).
std::string library_bands_csv(const std::vector<MaterialBands>& materials);

}  // namespace admitgen::io

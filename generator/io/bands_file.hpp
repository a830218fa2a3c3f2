// SPDX-License-Identifier: MIT
/// @file
/// The band-absorption file of `admitgen emit --bands-json` (docs/formats.md, "Band absorption"), schema
/// "admitgen.bands/1": octave and one-third-octave absorption, normal and random incidence, of the
/// emitted model, and a library's band files. Their one writer each (nothing reads them back), driven by one
/// field list per record (io/record_fields.hpp).
#pragma once

#include "codegen/emission.hpp"
#include "io/key_table.hpp"

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
/// The same numbers as CSV, one row per material and band (shortest round-trip numbers), the band's columns
/// named by its field list's keys.
std::string library_bands_csv(const std::vector<MaterialBands>& materials);

/// The keys of the two band files as their field lists name them (the tables of docs/formats.md, "Band
/// absorption").
std::vector<KeyNode> bands_keys();
std::vector<KeyNode> library_bands_keys();

}  // namespace admitgen::io

// SPDX-License-Identifier: MIT
/// @file
/// The band-absorption file of `admitgen emit --bands-json` (docs/formats.md, "Band absorption"), schema
/// "admitgen.bands/1": octave and one-third-octave absorption, normal and random incidence, of the
/// emitted model. Its one writer (nothing reads it back).
#pragma once

#include "codegen/emission.hpp"

#include <string>

namespace admitgen::io {

/// The file's text: JSON indented by 2, then a newline.
std::string bands_text(const codegen::Emission& emission);

}  // namespace admitgen::io

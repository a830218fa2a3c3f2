// SPDX-License-Identifier: MIT
/// @file
/// Reads a fit.json written by `admitgen fit` (shared by `emit` and `diagnose`).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace admitgen {

/// The parsed file. Throws FileError if it cannot be read or is not JSON (the schema is checked by
/// the consumers: multipole_from_fit, prepare_emission).
nlohmann::json read_fit_file(const std::string& path);

}  // namespace admitgen

/// @file
/// Reads a measured complex quantity from CSV/whitespace text and converts it to normalised
/// admittance (contract.md, "Input data"). Every malformed input is a FileError naming the file,
/// the line and the offending value.
#pragma once

#include "data/measurement.hpp"
#include "data/read_options.hpp"

#include <string>

namespace admitgen {

/// Reads and validates `path`. At least kMinimumPoints rows must remain after band selection.
Measurement read_measurement(const std::string& path, const ReadOptions& options);

inline constexpr int kMinimumPoints = 3;

}  // namespace admitgen

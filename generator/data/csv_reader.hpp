/// @file
/// Reads a measured complex quantity from an exported table (CSV, ';' or tab separated, blanks; decimal
/// point or comma; preamble, header and unit rows) and converts it to normalised admittance in
/// e^{+jωt} (docs/reading-data.md). Every malformed input is a FileError naming the file, the line and
/// the offending value; implausible readings are refused by data/plausibility.hpp.
#pragma once

#include "data/measurement.hpp"
#include "data/read_options.hpp"

#include <string>

namespace admitgen {

/// Reads and validates `path`. At least kMinimumPoints rows must remain after band selection.
Measurement read_measurement(const std::string& path, const ReadOptions& options);

inline constexpr int kMinimumPoints = 3;

}  // namespace admitgen

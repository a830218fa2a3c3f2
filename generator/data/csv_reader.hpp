// SPDX-License-Identifier: MIT
/// @file
/// Reads a measured complex quantity from an exported table (CSV, ';' or tab separated, blanks; decimal
/// point or comma; preamble, header and unit rows) and converts it to normalised admittance in
/// e^{+jωt} (docs/reading-data.md). Every malformed input is a FileError naming the file, the line and
/// the offending value; implausible readings are refused by data/plausibility.hpp.
#pragma once

#include "data/measurement.hpp"
#include "data/read_options.hpp"

#include <cstddef>
#include <string>

namespace admitgen {

/// Reads and validates `path`. At least kMinimumPoints rows must remain after band selection.
Measurement read_measurement(const std::string& path, const ReadOptions& options);

inline constexpr int kMinimumPoints = 3;

/// Limits that bound the memory a data file can take (docs/reading-data.md, "Limits"): a larger file is
/// refused before it is read in full (reading stops one byte past the limit), a file of more lines
/// before it is split. 200000 lines hold any tube or impedance-analyser export (a 10^5-point table is
/// ~10 MB); fitting more points than that takes days (`admitgen fit --cost-only` states the cost).
inline constexpr std::size_t kMaxDataFileBytes = std::size_t{16} << 20;
inline constexpr long kMaxDataFileLines = 200000;

}  // namespace admitgen

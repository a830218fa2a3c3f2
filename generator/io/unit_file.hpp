// SPDX-License-Identifier: MIT
/// @file
/// The result file of one library work unit (docs/library.md, "Work units"): one order's first-round run of a
/// fit (selection/fit.hpp, run_first_round), schema "admitgen.unit/2", plus the key of the inputs it was
/// computed from. Every number is written as a C99 hexadecimal float, so a unit read back is the run bit for
/// bit (a merge from unit files equals the fit that ran them in one process). Its one writer and one reader,
/// driven by one field list (io/record_fields.hpp).
#pragma once

#include "io/key_table.hpp"
#include "selection/fit.hpp"

#include <string>
#include <vector>

namespace admitgen::io {

struct UnitResult {
  std::string key;  ///< sha256 of everything the run depends on (library/plan.hpp)
  ModelResult model{Order(0, 0), {}, 0, 0.0, {}};
};

/// The file's text (line-oriented; a last line "end" marks a whole file).
std::string unit_text(const UnitResult& unit);

/// Reads a unit file; throws FileError naming the file and line on any malformed or missing entry. The
/// parameter summaries are recomputed from the run (inference/posterior.hpp, summarize), as fit_order does.
UnitResult read_unit_file(const std::string& path);

/// The keys of a unit file, one line each in this order, as its field list names them (the table of
/// docs/formats.md, "Library unit results").
std::vector<KeyNode> unit_keys();

/// The key stored in a unit file, or empty if the file is missing or not a whole unit file (a stale or
/// partial result is then simply redone).
std::string unit_file_key(const std::string& path);

}  // namespace admitgen::io

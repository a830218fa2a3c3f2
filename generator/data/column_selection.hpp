// SPDX-License-Identifier: MIT
/// @file
/// Which columns of a table hold the frequency and the two parts of the complex value, which
/// quantity that value is, and in which units (docs/reading-data.md, "Options" and "Column names"): from
/// --columns by position or by header name, or from the header's names alone.
#pragma once

#include "data/column_names.hpp"
#include "data/read_options.hpp"
#include "data/text_table.hpp"

#include <string>

namespace admitgen {

struct ColumnSelection {
  std::size_t width = 3;  ///< fields every data row must have
  std::size_t f = 0, first = 1, second = 2;  ///< frequency; re or mag; im or phase
  bool polar = false;
  Quantity quantity = Quantity::admittance;
  bool quantity_from_header = false;
  UnitKind f_unit = UnitKind::none, first_unit = UnitKind::none, second_unit = UnitKind::none;
  bool named_normalised = false;  ///< a selected value column's name says normalised (Z/Z0, ratio)
  std::string describe;           ///< e.g. "f = column 1 'Frequency [Hz]', re = column 2 'Re(Z/Z0)', ..."
};

/// Throws FileError naming the file (and the header's names) when the columns cannot be chosen,
/// including the absorption-only case (why α alone is not enough and what to supply instead).
ColumnSelection select_columns(const std::string& path, const TextTable& table, const ReadOptions& options);

/// The message for absorption-only data (docs/reading-data.md, "Absorption-only data").
std::string absorption_only_message();

}  // namespace admitgen

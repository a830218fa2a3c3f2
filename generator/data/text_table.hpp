// SPDX-License-Identifier: MIT
/// @file
/// The layout of an exported table (docs/reading-data.md): delimiter and decimal separator (given or
/// sniffed), quoted fields, the preamble of metadata lines, an optional header line of column names,
/// optional unit rows below it, and the data rows. Knows nothing of what the columns mean.
#pragma once

#include "data/read_options.hpp"

#include <optional>
#include <string>
#include <vector>

namespace admitgen {

struct TextLine {
  long number = 0;                  ///< 1-based line number in the file
  std::vector<std::string> fields;  ///< trimmed, quotes removed
};

struct TextTable {
  char delimiter = ',';  ///< ',' ';' '\t' or ' ' (runs of blanks and tabs)
  char decimal = '.';
  bool delimiter_sniffed = false, decimal_sniffed = false;
  std::optional<TextLine> header;  ///< column names, if the file has them
  std::vector<TextLine> unit_rows;  ///< rows of units (Hz, dB, deg, Pa s/m, -) between header and data
  long preamble_lines = 0;          ///< non-comment lines before header and data that were skipped
  std::vector<TextLine> rows;       ///< every data row (not yet checked to be numeric)

  /// One line for humans and fit.json, e.g. "';'-delimited (sniffed), decimal ',' (sniffed), 3 preamble lines, header line 4, 1 unit row, data from line 6".
  std::string describe() const;
};

/// Splits `text` (BOM and CR already removed or not) into a TextTable. Lines starting with '#' and
/// blank lines are comments. The data start at the first line whose fields are all numbers (at
/// least two), or earlier when the lines just above have the same field count and numbers in them
/// (a malformed first row is then reported, not skipped). Throws FileError naming the file when no
/// data row exists.
TextTable split_table(const std::string& path, const std::string& text, const TextFormat& format);

/// The field as a number under the table's decimal separator.
std::optional<double> parse_field(const TextTable& table, const std::string& field);

}  // namespace admitgen

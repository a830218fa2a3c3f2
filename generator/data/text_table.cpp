// SPDX-License-Identifier: MIT
#include "data/text_table.hpp"

#include "core/text.hpp"

#include "core/errors.hpp"
#include "data/column_names.hpp"
#include "data/number_parsing.hpp"

#include <algorithm>
#include <array>
#include <sstream>

namespace admitgen {
namespace {

struct RawLine {
  long number;
  std::string text;
};

/// Non-comment, non-blank lines after the first `skip` lines; CR and a UTF-8 BOM removed.
std::vector<RawLine> content_lines(const std::string& text, int skip) {
  std::vector<RawLine> out;
  std::istringstream in(text);
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number <= skip) continue;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    out.push_back({number, line});
  }
  return out;
}

/// Fields of one line: split at `delimiter` outside double quotes (' ' = runs of blanks and tabs),
/// each trimmed, enclosing quotes removed and "" inside quotes read as one quote (RFC 4180).
std::vector<std::string> tokenize(const std::string& line, char delimiter) {
  std::vector<std::string> fields;
  std::string current;
  bool quoted = false, any = false;
  const bool blanks = delimiter == ' ';
  const auto flush = [&] {
    if (!blanks || any) fields.push_back(blanks ? current : std::string(trim(current)));
    current.clear();
    any = false;
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"') {
      if (quoted && i + 1 < line.size() && line[i + 1] == '"') {
        current += '"';
        ++i;
      } else {
        quoted = !quoted;
      }
      any = true;
    } else if (!quoted && (blanks ? (c == ' ' || c == '\t') : c == delimiter)) {
      flush();
    } else {
      if (!(blanks && (c == ' ' || c == '\t'))) any = true;
      current += c;
    }
  }
  flush();
  return fields;
}

/// At least two fields, all numbers (an empty last field, left by a delimiter ending the line, aside).
bool all_numeric(const std::vector<std::string>& fields, char decimal) {
  const auto end = !fields.empty() && fields.back().empty() ? fields.end() - 1 : fields.end();
  return end - fields.begin() >= 2 &&
         std::all_of(fields.begin(), end, [&](const std::string& f) { return parse_double(f, decimal).has_value(); });
}

bool any_numeric(const std::vector<std::string>& fields, char decimal) {
  return std::any_of(fields.begin(), fields.end(), [&](const std::string& f) { return parse_double(f, decimal).has_value(); });
}

/// A row of units: every field empty or a known unit, at least one not empty.
bool unit_row(const std::vector<std::string>& fields) {
  bool some = false;
  for (const auto& f : fields) {
    if (f.empty()) continue;
    if (!is_known_unit(normalise_unit(f, true))) return false;
    some = true;
  }
  return some;
}

struct Layout {
  char delimiter, decimal;
};

/// Sniffing: every (delimiter, decimal) pair allowed by `format` is tried on the first lines; the one
/// under which most lines are all numbers wins; ties go to the earlier pair in the order
/// ';' '\t' ',' ' ' and '.' before ',' (so "1;2;3" reads with '.', and a tab-separated file is not
/// taken for blank-separated). The pair ',' ',' only wins with quoted fields ("0,5"): unquoted, every
/// line it reads as numbers reads so under ',' '.' too (integers), and the tie goes to '.'.
Layout sniff(const std::vector<RawLine>& lines, const TextFormat& format) {
  constexpr std::size_t kSniffLines = 200;
  Layout best{format.delimiter.value_or(','), format.decimal.value_or('.')};
  std::size_t best_score = 0;
  for (char d : {';', '\t', ',', ' '}) {
    if (format.delimiter && *format.delimiter != d) continue;
    for (char p : {'.', ','}) {
      if (format.decimal && *format.decimal != p) continue;
      std::size_t score = 0;
      for (std::size_t i = 0; i < std::min(lines.size(), kSniffLines); ++i)
        score += all_numeric(tokenize(lines[i].text, d), p) ? 1 : 0;
      if (score > best_score) best = {d, p}, best_score = score;
    }
  }
  return best;
}

/// Drops a trailing empty field from every line when all data rows have one (exports that end each
/// line with the delimiter).
void drop_trailing_delimiters(std::vector<TextLine>& lines, std::size_t data_start) {
  for (std::size_t i = data_start; i < lines.size(); ++i)
    if (lines[i].fields.size() < 2 || !lines[i].fields.back().empty()) return;
  for (auto& line : lines)
    if (!line.fields.empty() && line.fields.back().empty()) line.fields.pop_back();
}

}  // namespace

std::optional<double> parse_field(const TextTable& table, const std::string& field) {
  return parse_double(field, table.decimal);
}

TextTable split_table(const std::string& path, const std::string& text, const TextFormat& format) {
  const auto raw = content_lines(text, format.skip_rows);
  const Layout layout = sniff(raw, format);
  TextTable table;
  table.delimiter = layout.delimiter;
  table.decimal = layout.decimal;
  table.delimiter_sniffed = !format.delimiter;
  table.decimal_sniffed = !format.decimal;
  std::vector<TextLine> lines;
  for (const auto& r : raw) lines.push_back({r.number, tokenize(r.text, layout.delimiter)});
  auto start = std::find_if(lines.begin(), lines.end(), [&](const TextLine& l) { return all_numeric(l.fields, layout.decimal); });
  if (start == lines.end()) throw FileError(path, 0, "no data rows");
  auto data = static_cast<std::size_t>(start - lines.begin());
  drop_trailing_delimiters(lines, data);
  const std::size_t width = lines[data].fields.size();
  const auto same_width = [&](std::size_t i) { return lines[i].fields.size() == width; };
  while (data > 0 && same_width(data - 1) && !unit_row(lines[data - 1].fields) &&
         any_numeric(lines[data - 1].fields, layout.decimal))
    --data;  // a malformed first row: read (and reported) as data, not skipped
  std::size_t top = data;
  while (top > 0 && lines[top - 1].fields.size() <= width && unit_row(lines[top - 1].fields)) --top;
  if (top > 0 && same_width(top - 1) && !any_numeric(lines[top - 1].fields, layout.decimal)) {
    --top;
    table.header = lines[top];
  }
  for (std::size_t i = table.header ? top + 1 : top; i < data; ++i) table.unit_rows.push_back(lines[i]);
  table.preamble_lines = static_cast<long>(top);
  table.rows.assign(lines.begin() + static_cast<long>(data), lines.end());
  return table;
}

std::string TextTable::describe() const {
  const auto sniffed = [](bool s) { return s ? " (sniffed)" : ""; };
  std::string d = delimiter == '\t' ? "tab" : delimiter == ' ' ? "blank" : fmt::format("'{}'", delimiter);
  std::string out = fmt::format("{}-delimited{}, decimal '{}'{}", d, sniffed(delimiter_sniffed), decimal,
                                sniffed(decimal_sniffed));
  if (preamble_lines > 0) out += fmt::format(", {} preamble line(s) skipped", preamble_lines);
  if (header) out += fmt::format(", header on line {}", header->number);
  if (!unit_rows.empty()) out += fmt::format(", {} unit row(s)", unit_rows.size());
  if (!rows.empty()) out += fmt::format(", data from line {}", rows.front().number);
  return out;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The HTML around the reports: one self-contained page (inline CSS and SVG, no script, no font, no
/// network), styled with CSS variables so it reads on light and dark backgrounds and prints on white.
/// Helpers for tables and definition lists keep the report builders to content.
#pragma once

#include <string>
#include <vector>

namespace admitgen::report {

/// A complete HTML document: <head> with `title` and the stylesheet, `body` inside <main>, and a
/// footer line naming the admitgen version.
std::string page(const std::string& title, const std::string& body);

/// A table; `header` and every row hold HTML (escape text with plot::escape_xml). Columns listed in
/// `numeric` (0-based) are right-aligned in tabular figures. `row_classes[i]`, if given, classes row i.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::size_t> numeric;
  std::vector<std::string> row_classes;
  std::string caption;
};
std::string html(const Table& table);

/// A <figure> holding SVG (or other HTML) and a caption (HTML).
std::string figure(const std::string& content, const std::string& caption);

/// <dl> of term/description pairs (both HTML).
std::string definitions(const std::vector<std::pair<std::string, std::string>>& items);

/// Warning box listing each warning (plain text), or nothing if there are none.
std::string warnings_box(const std::vector<std::string>& warnings);

}  // namespace admitgen::report

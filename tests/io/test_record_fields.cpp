// SPDX-License-Identifier: MIT
// Each record's fields are declared once (io/record_fields.hpp): its field list drives the writer, the reader
// and the key table of docs/formats.md. A file's table there must list exactly the objects and keys of its
// field list, in order, with the same marks; the round trips are tests/io/test_record_files.cpp and
// tests/library/test_library.cpp.
#include "io/bands_file.hpp"
#include "io/check_report.hpp"
#include "io/diagnosis_file.hpp"
#include "io/fit_file.hpp"
#include "io/key_table.hpp"
#include "io/unit_file.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace admitgen;
using admitgen::test::read_text;
using admitgen::test::sample;

namespace {

using Rows = std::vector<std::pair<std::string, std::string>>;

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// The cells of a Markdown table row ("| a | b | c |").
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 1;
  for (std::size_t i = 1; i < line.size(); ++i)
    if (line[i] == '|' && line[i - 1] != '\\') {
      out.push_back(trimmed(line.substr(start, i - start)));
      start = i + 1;
    }
  return out;
}

/// The object and keys columns of the key table ("| object | keys | … |") that follows `heading` in
/// docs/formats.md (the `skip` + 1st under it); the object column's backticks removed, "(document)" read as "".
Rows documented_rows(const std::string& heading, int skip) {
  std::istringstream in(read_text(sample("..") + "/docs/" + "formats.md"));
  std::string line;
  while (std::getline(in, line) && line != heading) {
  }
  REQUIRE_MESSAGE(in, "docs/formats.md has no heading " << heading);
  for (int table = 0; table <= skip; ++table)
    while (std::getline(in, line) && line.rfind("| object | keys |", 0) != 0 && line.rfind("## ", 0) != 0) {
    }
  REQUIRE_MESSAGE(line.rfind("| object | keys |", 0) == 0, "no key table under " << heading);
  std::getline(in, line);  // |---|---|
  Rows rows;
  while (std::getline(in, line) && line.rfind("|", 0) == 0) {
    const auto c = cells(line);
    REQUIRE(c.size() >= 2);
    std::string object = c[0] == "(document)" ? "" : c[0];
    if (object.size() > 2 && object.front() == '`' && object.back() == '`') object = object.substr(1, object.size() - 2);
    rows.emplace_back(object, c[1]);
  }
  return rows;
}

/// The table as it should stand (empty notes), for the message of a failure.
std::string markdown(const Rows& rows) {
  std::string s = "| object | keys | notes |\n|---|---|---|\n";
  for (const auto& [object, keys] : rows)
    s += "| " + (object.empty() ? std::string("(document)") : "`" + object + "`") + " | " + keys + " | |\n";
  return s;
}

void check_table(const std::string& heading, const std::vector<io::KeyNode>& keys, int skip = 0) {
  const Rows expected = io::key_table_rows(keys), documented = documented_rows(heading, skip);
  INFO("the key table under " << heading << " in docs/formats.md should read (notes aside):\n" << markdown(expected));
  CHECK(documented == expected);
}

}  // namespace

TEST_CASE("docs/formats.md: the key tables are the field lists of fit.json, diagnosis.json, unit and band files") {
  check_table("## fit.json (`admitgen.fit/1`)", io::fit_keys());
  check_table("## diagnosis.json (`admitgen.diagnosis/3`)", io::diagnosis_keys());
  check_table("## Library unit results (`admitgen.unit/2`)", io::unit_keys());
  check_table("## Band absorption (`admitgen.bands/1`)", io::bands_keys());
  check_table("## Band absorption (`admitgen.bands/1`)", io::library_bands_keys(), 1);
}

TEST_CASE("key table: objects get rows of their own, marks say optional, arrays and keyed objects") {
  using S = io::KeyNode::Shape;
  const std::vector<io::KeyNode> keys = {
      {"a", false, S::value, {}},
      {"b", true, S::object, {{"c", false, S::value, {}}}},
      {"d", false, S::records, {{"e", true, S::keyed, {}}}},
      {"f", false, S::keyed_records, {{"g", false, S::value, {}, true}}}};
  const Rows rows = io::key_table_rows(keys);
  REQUIRE(rows.size() == 4);
  CHECK(rows[0] == std::make_pair(std::string(), std::string("`a`, `b`? {}, `d` [{}], `f` {name: {}}")));
  CHECK(rows[1] == std::make_pair(std::string("b"), std::string("`c`")));
  CHECK(rows[2] == std::make_pair(std::string("d[]"), std::string("`e`? {name: …}")));
  CHECK(rows[3] == std::make_pair(std::string("f{}"), std::string("`g` or null")));
}

/// Every key of `keys` and of the objects under them, in backticks.
void collect_keys(const std::vector<io::KeyNode>& keys, std::vector<std::string>& out) {
  for (const auto& k : keys) {
    out.push_back("`" + k.key + "`");
    collect_keys(k.children, out);
  }
}

TEST_CASE("docs/formats.md: the check report's key table and details rows name the field lists' keys") {
  check_table("## check report (`admitgen.check/1`)", io::check_report_keys());
  // The details differ per check: its row of the details table names every key of its record.
  const std::string doc = read_text(sample("..") + "/docs/" + "formats.md");
  for (const auto& [check, keys] : io::check_details_keys()) {
    CAPTURE(check);
    const auto row = doc.find("| `" + check + "` | ");
    REQUIRE(row != std::string::npos);
    const std::string line = doc.substr(row, doc.find('\n', row) - row);
    std::vector<std::string> names;
    collect_keys(keys, names);
    for (const auto& name : names) CHECK_MESSAGE(line.find(name) != std::string::npos, name << " in " << line);
  }
}

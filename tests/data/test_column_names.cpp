// SPDX-License-Identifier: MIT
// Header-name matching and table layout (docs/reading-data.md, "Column names", "Layout and
// sniffing"): what each spelling tool exports reduces to, and where header, unit rows and data are.
#include "core/errors.hpp"
#include "data/column_names.hpp"
#include "data/number_parsing.hpp"
#include "data/text_table.hpp"

#include <doctest/doctest.h>

using namespace admitgen;
using Kind = ColumnMeaning::Kind;

TEST_CASE("column names: spellings of tube software and spreadsheets are recognised") {
  struct Case {
    const char* header;
    Kind kind;
    Quantity quantity;
    Part part;
    bool normalised;
  };
  const Case cases[] = {
      {"Re(Z/Z0)", Kind::value, Quantity::impedance, Part::re, true},
      {"Im(Z/Z0)", Kind::value, Quantity::impedance, Part::im, true},
      {"Specific_Resistance_Ratio", Kind::value, Quantity::impedance, Part::re, true},
      {"Specific Reactance Ratio", Kind::value, Quantity::impedance, Part::im, true},
      {"Re_y", Kind::value, Quantity::admittance, Part::re, false},
      {"Im(β)", Kind::value, Quantity::admittance, Part::im, false},
      {"Re Z [Pa s/m]", Kind::value, Quantity::impedance, Part::re, false},
      {"Re(Zs/ρc)", Kind::value, Quantity::impedance, Part::re, true},
      {"|R| [dB]", Kind::value, Quantity::reflection, Part::mag, false},
      {"Phase(R) (deg)", Kind::value, Quantity::reflection, Part::phase, false},
      {"Reflection factor magnitude", Kind::value, Quantity::reflection, Part::mag, false},
      {"R_real", Kind::value, Quantity::reflection, Part::re, false},
      {"Frequency [Hz]", Kind::frequency, Quantity::admittance, Part::re, false},
      {"Frequenz / Hz", Kind::frequency, Quantity::admittance, Part::re, false},
      {"f_Hz", Kind::frequency, Quantity::admittance, Part::re, false},
      {"Absorption coefficient", Kind::absorption, Quantity::admittance, Part::re, false},
      {"α", Kind::absorption, Quantity::admittance, Part::re, false},
      {"Sample", Kind::unknown, Quantity::admittance, Part::re, false},
      {"re", Kind::unknown, Quantity::admittance, Part::re, false},
  };
  for (const Case& c : cases) {
    INFO(c.header);
    const ColumnMeaning m = classify_column(c.header);
    CHECK(m.kind == c.kind);
    if (c.kind != Kind::value) continue;
    CHECK(m.quantity == c.quantity);
    CHECK(m.part == c.part);
    CHECK(m.normalised == c.normalised);
  }
  CHECK(split_name_unit("f_kHz").second == "kHz");
  // ISO 80000-1 "quantity/unit" without spaces; a unit keeps its own slash; a ratio is not a unit.
  CHECK(split_name_unit("f/kHz") == std::pair<std::string, std::string>{"f", "kHz"});
  CHECK(classify_column("f/kHz").kind == Kind::frequency);
  CHECK(split_name_unit("Re Z/Pa s/m") == std::pair<std::string, std::string>{"Re Z", "Pa s/m"});
  CHECK(split_name_unit("phi/deg").second == "deg");
  CHECK(split_name_unit("Z/Z0").second.empty());
  CHECK(split_name_unit("Re(Z/rho c)").second.empty());
  CHECK(classify_column("Re Z/Z0").normalised);
  CHECK(classify_column("FkHz").implied_unit == UnitKind::kilohertz);
  CHECK(normalise_name("RE Z/Z0 [-]") == normalise_name("re_z/z0"));
  CHECK(unit_kind(normalise_unit("[Pa·s/m]", true)) == UnitKind::si_impedance);
  CHECK(unit_kind(normalise_unit("°", true)) == UnitKind::degrees);
  CHECK_FALSE(unit_kind(normalise_unit("furlong", true)).has_value());
}

TEST_CASE("number parsing: decimal comma, and no guessing of thousands separators") {
  CHECK(parse_double("0,125", ',') == 0.125);
  CHECK(parse_double("-1,5e3", ',') == -1500.0);
  CHECK_FALSE(parse_double("1.234,5", ',').has_value());
  CHECK_FALSE(parse_double("1,2,3", ',').has_value());
  CHECK_FALSE(parse_double("0,5", '.').has_value());
}

TEST_CASE("table layout: sniffing, quotes, preamble, header, unit rows and a malformed first row") {
  const auto split = [](const std::string& text, TextFormat f = {}) { return split_table("t.csv", text, f); };
  const TextTable tab = split("a b c\n100\t1.5\t2\n200\t3\t4\n");
  CHECK(tab.delimiter == '\t');  // a tie with blanks goes to tab
  const TextTable eu = split("Probe: 7\nf;Re;Im\nHz;-;-\n100;0,5;1\n200;0,25;2\n");
  CHECK(eu.delimiter == ';');
  CHECK(eu.decimal == ',');
  REQUIRE(eu.header);
  CHECK(eu.header->number == 2);
  CHECK(eu.unit_rows.size() == 1);
  CHECK(eu.preamble_lines == 1);
  CHECK(eu.rows.size() == 2);
  const TextTable quoted = split("\"f\",\"Re, part\",\"Im\"\n100,\"0,5\",\"1,5\"\n");
  CHECK(quoted.decimal == ',');
  CHECK(quoted.header->fields[1] == "Re, part");
  CHECK(quoted.rows[0].fields == std::vector<std::string>{"100", "0,5", "1,5"});
  const TextTable ints = split("100,0,5,0,3\n200,1,5,0,25\n");  // unquoted: never a decimal comma
  CHECK(ints.decimal == '.');
  CHECK(ints.rows[0].fields.size() == 5);
  const TextTable bad = split("f,re,im\n100,abc,0.3\n200,0.2,0.3\n");  // reported, not skipped
  CHECK(bad.rows.front().number == 2);
  REQUIRE(bad.header);
  CHECK(bad.header->number == 1);
  CHECK_THROWS_WITH_AS(split("only,text\nhere,too\n"), "t.csv: no data rows", FileError);
  TextFormat forced;
  forced.delimiter = ',';
  CHECK(split("100;1;2\n1,2,3\n", forced).rows.size() == 1);
}

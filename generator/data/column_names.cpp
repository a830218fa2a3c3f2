// SPDX-License-Identifier: MIT
#include "data/column_names.hpp"

#include "core/text.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace admitgen {
namespace {

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
}

std::string lower_ascii(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

/// Blanks, tabs and quotes off both ends (a header name may be quoted).
std::string trim_name(const std::string& s) { return std::string(trim(s, " \t\"'")); }

const std::map<std::string, UnitKind>& units() {
  static const std::map<std::string, UnitKind> table{
      {"hz", UnitKind::hertz},           {"1/s", UnitKind::hertz},          {"khz", UnitKind::kilohertz},
      {"db", UnitKind::decibel},         {"deg", UnitKind::degrees},        {"rad", UnitKind::radians},
      {"-", UnitKind::dimensionless},    {"1", UnitKind::dimensionless},    {"pas/m", UnitKind::si_impedance},
      {"rayl", UnitKind::si_impedance},  {"rayls", UnitKind::si_impedance}, {"ns/m3", UnitKind::si_impedance},
      {"ns/m^3", UnitKind::si_impedance}, {"kg/(m2s)", UnitKind::si_impedance}, {"kg/m2s", UnitKind::si_impedance},
      {"kg/(m^2s)", UnitKind::si_impedance}, {"m/(pas)", UnitKind::si_admittance}, {"m/pas", UnitKind::si_admittance},
      {"m3/(ns)", UnitKind::si_admittance}};
  return table;
}

/// Symbols naming a quantity, in the reduced spelling of normalise_name.
const std::map<std::string, Quantity>& symbols() {
  static const std::map<std::string, Quantity> table{
      {"z", Quantity::impedance},        {"zs", Quantity::impedance},      {"zn", Quantity::impedance},
      {"impedance", Quantity::impedance}, {"surfaceimpedance", Quantity::impedance},
      {"y", Quantity::admittance},       {"ys", Quantity::admittance},     {"yn", Quantity::admittance},
      {"beta", Quantity::admittance},    {"admittance", Quantity::admittance},
      {"surfaceadmittance", Quantity::admittance},
      {"r", Quantity::reflection},       {"reflection", Quantity::reflection},
      {"reflectionfactor", Quantity::reflection}, {"reflectioncoefficient", Quantity::reflection}};
  return table;
}

/// Part names, longest spelling first so "real" is not read as "re" + "al".
constexpr std::array<std::pair<const char*, Part>, 14> kParts{{{"imaginary", Part::im}, {"magnitude", Part::mag},
                                                               {"amplitude", Part::mag}, {"modulus", Part::mag},
                                                               {"angle", Part::phase}, {"phase", Part::phase},
                                                               {"real", Part::re}, {"imag", Part::im},
                                                               {"abs", Part::mag}, {"mag", Part::mag},
                                                               {"arg", Part::phase}, {"phi", Part::phase},
                                                               {"re", Part::re}, {"im", Part::im}}};

/// Names that are words rather than part + symbol (ISO 10534-2 and tube-software vocabulary).
const std::map<std::string, std::pair<Quantity, Part>>& words() {
  static const std::map<std::string, std::pair<Quantity, Part>> table{
      {"resistance", {Quantity::impedance, Part::re}},   {"reactance", {Quantity::impedance, Part::im}},
      {"specificresistance", {Quantity::impedance, Part::re}}, {"specificreactance", {Quantity::impedance, Part::im}},
      {"conductance", {Quantity::admittance, Part::re}}, {"susceptance", {Quantity::admittance, Part::im}},
      {"specificconductance", {Quantity::admittance, Part::re}},
      {"specificsusceptance", {Quantity::admittance, Part::im}}};
  return table;
}

bool strip_suffix(std::string& s, const std::string& suffix) {
  if (s.size() <= suffix.size() || s.compare(s.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
  s.erase(s.size() - suffix.size());
  return true;
}

bool strip_prefix(std::string& s, const std::string& prefix) {
  if (s.size() <= prefix.size() || s.compare(0, prefix.size(), prefix) != 0) return false;
  s.erase(0, prefix.size());
  return true;
}

/// Removes the markers of normalisation ("/z0", "/rhoc", "ratio", "normalised") and says if any was there.
bool strip_normalisation(std::string& n) {
  bool found = false;
  for (const char* s : {"/z0", "/zo", "/zc", "/rhoc", "/rho0c0", "/rhoc0", "/rho0c", "/y0", "ratio"})
    found = strip_suffix(n, s) || found;
  for (const char* p : {"normalised", "normalized", "norm"}) found = strip_prefix(n, p) || found;
  return found;
}

std::optional<std::pair<Quantity, Part>> part_and_symbol(const std::string& n) {
  if (const auto w = words().find(n); w != words().end()) return w->second;
  if (n.size() > 2 && n.front() == '|' && n.back() == '|')
    if (const auto s = symbols().find(n.substr(1, n.size() - 2)); s != symbols().end()) return std::pair{s->second, Part::mag};
  for (const auto& [name, part] : kParts) {
    const std::string p(name);
    if (n.size() > p.size() && n.compare(0, p.size(), p) == 0)
      if (const auto s = symbols().find(n.substr(p.size())); s != symbols().end()) return std::pair{s->second, part};
    if (n.size() > p.size() && n.compare(n.size() - p.size(), p.size(), p) == 0)
      if (const auto s = symbols().find(n.substr(0, n.size() - p.size())); s != symbols().end())
        return std::pair{s->second, part};
  }
  return std::nullopt;
}

}  // namespace

std::string normalise_unit(const std::string& text, bool whole_field) {
  std::string u = trim_name(text);
  if (whole_field && u.size() >= 2 && ((u.front() == '[' && u.back() == ']') || (u.front() == '(' && u.back() == ')')))
    u = u.substr(1, u.size() - 2);
  replace_all(u, "\xC2\xB0", "deg");  // °
  replace_all(u, "\xC2\xB7", "");     // ·
  replace_all(u, "\xE2\x8B\x85", "");  // ⋅
  replace_all(u, "\xC2\xB3", "3");    // ³
  replace_all(u, "\xC2\xB2", "2");    // ²
  u = lower_ascii(u);
  u.erase(std::remove_if(u.begin(), u.end(), [](char c) { return c == ' ' || c == '.' || c == '*'; }), u.end());
  if (u == "degree" || u == "degrees") u = "deg";
  if (u == "radian" || u == "radians") u = "rad";
  return u;
}

std::optional<UnitKind> unit_kind(const std::string& u) {
  if (u.empty()) return UnitKind::none;
  const auto it = units().find(u);
  if (it == units().end()) return std::nullopt;
  return it->second;
}

std::pair<std::string, std::string> split_name_unit(const std::string& field) {
  const std::string f = trim_name(field);
  const auto open = f.rfind('[');
  if (open != std::string::npos && f.find(']', open) != std::string::npos) {
    const auto close = f.find(']', open);
    return {trim_name(f.substr(0, open) + f.substr(close + 1)), f.substr(open + 1, close - open - 1)};
  }
  const auto paren = f.rfind('(');
  if (!f.empty() && f.back() == ')' && paren != std::string::npos) {
    const std::string inside = f.substr(paren + 1, f.size() - paren - 2);
    if (!normalise_unit(inside, false).empty() && is_known_unit(normalise_unit(inside, false)))
      return {trim_name(f.substr(0, paren)), inside};
  }
  const auto underscore = f.rfind('_');  // "f_Hz", "f_kHz"
  if (underscore != std::string::npos && underscore + 1 < f.size()) {
    const std::string tail = normalise_unit(f.substr(underscore + 1), false);
    if (tail != "1" && !tail.empty() && is_known_unit(tail)) return {f.substr(0, underscore), f.substr(underscore + 1)};
  }
  const auto slash = f.rfind(" / ");
  if (slash != std::string::npos && is_known_unit(normalise_unit(f.substr(slash + 3), false)))
    return {trim_name(f.substr(0, slash)), f.substr(slash + 3)};
  // ISO 80000-1 "quantity/unit" without spaces ("f/kHz", "Z/Pa s/m"): the first slash after which the rest
  // is a unit (so a unit with its own slash stays whole); "Z/Z0" or "Re(Z/rho c)" have none.
  for (auto at = f.find('/'); at != std::string::npos && at > 0; at = f.find('/', at + 1)) {
    const std::string unit = trim_name(f.substr(at + 1));
    const std::string reduced = normalise_unit(unit, false);
    if (!reduced.empty() && reduced != "1" && is_known_unit(reduced)) return {trim_name(f.substr(0, at)), unit};
  }
  return {f, {}};
}

std::string normalise_name(const std::string& field) {
  std::string n = split_name_unit(field).first;
  replace_all(n, "\xCE\xB1", "alpha");  // α
  replace_all(n, "\xCE\xB2", "beta");   // β
  replace_all(n, "\xCF\x81", "rho");    // ρ
  n = lower_ascii(n);
  n.erase(std::remove_if(n.begin(), n.end(),
                         [](char c) { return !((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '/' || c == '|'); }),
          n.end());
  return n;
}

ColumnMeaning classify_column(const std::string& header_field) {
  std::string n = normalise_name(header_field);
  ColumnMeaning m;
  for (const char* f : {"f", "freq", "frequency", "frequenz", "fhz", "freqhz", "frequencyhz", "fkhz", "freqkhz",
                        "frequencykhz"})
    if (n == f) {
      m.kind = ColumnMeaning::Kind::frequency;
      m.implied_unit = n.size() > 3 && n.compare(n.size() - 3, 3, "khz") == 0 ? UnitKind::kilohertz : UnitKind::none;
      return m;
    }
  for (const char* a : {"alpha", "alphan", "alpha0", "alfa", "absorption", "absorptioncoefficient", "absorptioncoeff",
                        "absorptioncoef"})
    if (n == a) {
      m.kind = ColumnMeaning::Kind::absorption;
      return m;
    }
  m.normalised = strip_normalisation(n);
  if (const auto ps = part_and_symbol(n)) {
    m.kind = ColumnMeaning::Kind::value;
    m.quantity = ps->first;
    m.part = ps->second;
  }
  return m;
}

}  // namespace admitgen

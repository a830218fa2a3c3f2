// SPDX-License-Identifier: MIT
#include "data/read_options.hpp"

#include "core/errors.hpp"
#include "data/number_parsing.hpp"

#include <algorithm>
#include <sstream>

namespace admitgen {

Quantity parse_quantity(const std::string& text) {
  if (text == "admittance") return Quantity::admittance;
  if (text == "impedance") return Quantity::impedance;
  if (text == "reflection") return Quantity::reflection;
  throw InputError(fmt::format("{} '{}': expected admittance, impedance or reflection", setting("quantity"), text));
}

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::admittance: return "admittance";
    case Quantity::impedance: return "impedance";
    case Quantity::reflection: return "reflection";
  }
  throw InternalError("unhandled Quantity");
}

MagnitudeScale parse_magnitude_scale(const std::string& text) {
  if (text == "linear") return MagnitudeScale::linear;
  if (text == "db" || text == "dB") return MagnitudeScale::decibel;
  throw InputError(fmt::format("{} '{}': expected linear or db", setting("magnitude"), text));
}

PhaseUnit parse_phase_unit(const std::string& text) {
  if (text == "deg") return PhaseUnit::degrees;
  if (text == "rad") return PhaseUnit::radians;
  throw InputError(fmt::format("{} '{}': expected deg or rad", setting("phase"), text));
}

TimeConvention parse_time_convention(const std::string& text) {
  if (text == "+jwt") return TimeConvention::plus_jwt;
  if (text == "-jwt") return TimeConvention::minus_jwt;
  throw InputError(fmt::format("{} '{}': expected +jwt (e^{{+jwt}}, engineering) or -jwt "
                               "(e^{{-iwt}}, physics)", setting("time_convention"), text));
}

Band Band::parse(const std::string& text) {
  const auto colon = text.find(':');
  const auto bad = [&](const char* why) {
    return InputError(fmt::format("{} '{}': {} (expected FMIN:FMAX in Hz, e.g. 200:1600)", setting("band"), text, why));
  };
  if (colon == std::string::npos) throw bad("missing ':'");
  const auto lo = parse_double(text.substr(0, colon));
  const auto hi = parse_double(text.substr(colon + 1));
  if (!lo || !hi) throw bad("not two numbers");
  if (!(*lo > 0.0)) throw bad("FMIN must be positive");
  if (!(*hi > *lo)) throw bad("FMAX must exceed FMIN");
  return Band{*lo, *hi};
}

const char* role_name(Role r) {
  switch (r) {
    case Role::f: return "f";
    case Role::re: return "re";
    case Role::im: return "im";
    case Role::mag: return "mag";
    case Role::phase: return "phase";
    case Role::skip: return "_";
  }
  throw InternalError("unhandled Role");
}

namespace {

std::optional<Role> role_from(const std::string& name) {
  for (Role r : {Role::f, Role::re, Role::im, Role::mag, Role::phase, Role::skip})
    if (name == role_name(r)) return r;
  return std::nullopt;
}

}  // namespace

bool ColumnMap::polar() const {
  const auto has_mag = [](Role r) { return r == Role::mag; };
  if (by_name()) return std::any_of(names.begin(), names.end(), [&](const auto& n) { return has_mag(n.first); });
  return std::any_of(positions.begin(), positions.end(), has_mag);
}

ColumnMap ColumnMap::parse(const std::string& spec) {
  ColumnMap map;
  map.spec = spec;
  const auto bad = [&](const std::string& why) {
    return InputError(fmt::format("{} '{}': {} (expected f, re, im (or mag, phase) and _ for skipped columns "
                                  "by position, e.g. f,_,_,_,_,re,im,_, or by header name, e.g. "
                                  "f=Frequency [Hz],re=Re(Z/Z0),im=Im(Z/Z0))", setting("columns"), spec, why));
  };
  const bool by_name = spec.find('=') != std::string::npos;
  std::vector<Role> seen;
  std::stringstream ss(spec);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    if (by_name != (eq != std::string::npos)) throw bad("mixes positions and names");
    const auto role = role_from(by_name ? item.substr(0, eq) : item);
    if (!role) throw bad(fmt::format("unknown column role '{}'", by_name ? item.substr(0, eq) : item));
    if (*role != Role::skip && std::count(seen.begin(), seen.end(), *role) > 0)
      throw bad(fmt::format("column '{}' named twice", role_name(*role)));
    seen.push_back(*role);
    if (by_name) {
      if (*role == Role::skip) throw bad("'_' has no meaning by name: list only the columns to read");
      if (eq + 1 >= item.size()) throw bad(fmt::format("no header name after '{}='", role_name(*role)));
      map.names.emplace_back(*role, item.substr(eq + 1));
    } else {
      map.positions.push_back(*role);
    }
  }
  const auto has = [&](Role r) { return std::count(seen.begin(), seen.end(), r) == 1; };
  const bool cartesian = has(Role::re) && has(Role::im), polar = has(Role::mag) && has(Role::phase);
  if (!has(Role::f) || cartesian == polar ||
      (cartesian && (has(Role::mag) || has(Role::phase))) || (polar && (has(Role::re) || has(Role::im))))
    throw bad("f and either re and im or mag and phase must each be named once");
  return map;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// What a column's header name and unit say (docs/reading-data.md, "Column names"): frequency,
/// absorption, or one part (re, im, magnitude, phase) of an admittance, impedance or reflection
/// factor, and whether the name marks it normalised ("Z/Z0", "ratio"). Matching ignores case,
/// blanks, '_', '-', parentheses and a unit suffix, so "Re(Z/Z0)", "re_z" and "Re Z [-]" agree.
#pragma once

#include "data/read_options.hpp"

#include <string>
#include <utility>

namespace admitgen {

enum class UnitKind { none, hertz, kilohertz, decibel, degrees, radians, dimensionless, si_impedance, si_admittance };

/// A unit as written ("[Hz]", "(deg)", "Pa·s/m", "°"), lower-cased with blanks, dots and '·'
/// removed; `whole_field` strips one pair of enclosing brackets first.
std::string normalise_unit(const std::string& text, bool whole_field);
/// The kind of a normalised unit; nullopt when admitgen does not know it.
std::optional<UnitKind> unit_kind(const std::string& normalised_unit);
inline bool is_known_unit(const std::string& u) { return unit_kind(u).has_value(); }

/// Splits "Frequency [Hz]", "Phase (deg)", "Frequenz / Hz" into name and unit text (unit empty if none).
std::pair<std::string, std::string> split_name_unit(const std::string& field);

/// The name reduced for matching: lower case, only letters, digits, '/' and '|' kept, Greek α β ρ
/// spelled out, unit suffix removed.
std::string normalise_name(const std::string& field);

enum class Part { re, im, mag, phase };

struct ColumnMeaning {
  enum class Kind { unknown, frequency, absorption, value } kind = Kind::unknown;
  Quantity quantity = Quantity::admittance;  ///< for values
  Part part = Part::re;                      ///< for values
  bool normalised = false;                   ///< the name says normalised (/Z0, /ρc, "ratio")
  UnitKind implied_unit = UnitKind::none;    ///< a unit inside the name, e.g. "f_kHz"
};

ColumnMeaning classify_column(const std::string& header_field);

}  // namespace admitgen

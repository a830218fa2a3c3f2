// SPDX-License-Identifier: MIT
/// @file
/// How to read a data file (docs/reading-data.md): the text layout (delimiter, decimal separator,
/// lines to skip), which columns hold what (by position or by header name), which quantity they are
/// (admittance, impedance, reflection factor; Cartesian or magnitude/phase; normalised or SI), the
/// time convention, and which band to keep. Every field left empty is found from the file (sniffed
/// or read from its header) or takes the documented default.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace admitgen {

enum class Quantity { admittance, impedance, reflection };
enum class MagnitudeScale { linear, decibel };  ///< decibel: 20·log10|x| (a field quantity)
enum class PhaseUnit { degrees, radians };
/// e^{+jωt} (engineering; admitgen's own) or e^{−jωt} (physics): the latter conjugates every value.
enum class TimeConvention { plus_jwt, minus_jwt };

/// Parses "admittance" | "impedance" | "reflection"; throws InputError otherwise.
Quantity parse_quantity(const std::string& text);
const char* quantity_name(Quantity q);
MagnitudeScale parse_magnitude_scale(const std::string& text);  ///< "linear" | "db"
PhaseUnit parse_phase_unit(const std::string& text);            ///< "deg" | "rad"
TimeConvention parse_time_convention(const std::string& text);  ///< "+jwt" | "-jwt"

/// A closed frequency interval [lo, hi] in Hz, 0 < lo < hi.
struct Band {
  double lo_hz;
  double hi_hz;
  /// Parses "FMIN:FMAX"; throws InputError naming the text if malformed or empty.
  static Band parse(const std::string& text);
};

/// What a selected column holds: frequency, the two parts of the complex value (re/im or
/// mag/phase), or nothing (`_`, skipped).
enum class Role { f, re, im, mag, phase, skip };
const char* role_name(Role r);

/// Column roles, either by position ("f,_,_,_,_,re,im,_": one entry per column of the file) or by
/// header name ("f=Frequency [Hz],re=Re(Z/Z0),im=Im(Z/Z0)": matched case-, blank- and
/// unit-insensitively against the header line). Exactly one f, and re+im or mag+phase.
struct ColumnMap {
  std::vector<Role> positions;                       ///< by position; empty when by name
  std::vector<std::pair<Role, std::string>> names;   ///< by header name; empty when by position
  std::string spec = "f,re,im";                      ///< as given
  bool by_name() const { return !names.empty(); }
  bool polar() const;  ///< mag/phase rather than re/im
  /// Throws InputError naming the spec if a role is missing, repeated, mixed or unknown.
  static ColumnMap parse(const std::string& spec);
};

/// Text layout. Empty delimiter/decimal = sniffed from the file (docs/reading-data.md, "Sniffing").
struct TextFormat {
  std::optional<char> delimiter;  ///< ',' ';' '\t' or ' ' (runs of blanks)
  std::optional<char> decimal;    ///< '.' or ','
  int skip_rows = 0;              ///< lines skipped unconditionally before anything else is read
};

struct ReadOptions {
  TextFormat format;
  std::optional<ColumnMap> columns;          ///< empty: from the header's names, else f,re,im
  std::optional<Quantity> quantity;          ///< empty: from the header's names, else admittance
  std::optional<double> rho_c;               ///< SI values: divide out ρ0c0 [Pa·s/m]; empty = normalised
  std::optional<MagnitudeScale> magnitude;   ///< empty: from the header's unit, else linear
  std::optional<PhaseUnit> phase;            ///< empty: from the header's unit, else an error
  std::optional<TimeConvention> time_convention;  ///< empty: e^{+jωt}, but checked (see plausibility.hpp)
  std::optional<Band> band;                  ///< keep only this range
  bool plausibility_errors = true;           ///< false: plausibility findings become warnings
};

}  // namespace admitgen

/// @file
/// How to read a data file (contract.md, "Input data"): which columns hold what, which quantity the
/// complex columns are, normalised or SI, and which band to keep.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace admitgen {

enum class Quantity { admittance, impedance, reflection };

/// Parses "admittance" | "impedance" | "reflection"; throws InputError otherwise.
Quantity parse_quantity(const std::string& text);

/// A closed frequency interval [lo, hi] in Hz, 0 < lo < hi.
struct Band {
  double lo_hz;
  double hi_hz;
  /// Parses "FMIN:FMAX"; throws InputError naming the text if malformed or empty.
  static Band parse(const std::string& text);
};

/// Column roles parsed from e.g. "f,_,_,_,_,re,im,_": exactly one f, re and im; `_` skips a column.
struct ColumnMap {
  int f = 0, re = 1, im = 2;
  int count = 3;  ///< number of columns every data row must have
  std::string spec = "f,re,im";  ///< as given
  /// Throws InputError naming the spec if a role is missing, repeated or unknown.
  static ColumnMap parse(const std::string& spec);
};

struct ReadOptions {
  ColumnMap columns;                   ///< default f,re,im
  Quantity quantity = Quantity::admittance;
  std::optional<double> rho_c;         ///< SI values: divide out ρ0c0 [Pa·s/m]; empty = normalised
  std::optional<Band> band;            ///< keep only this range
};

}  // namespace admitgen

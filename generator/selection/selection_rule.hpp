// SPDX-License-Identifier: MIT
/// @file
/// How an order is chosen from the evidence grid (docs/method.md, "Model selection"):
///   best         the highest ln Z;
///   cheapest:DB  the fewest state buffers (Q + 2S) among orders within DB deciban of the best
///                (ties broken by higher evidence) — the paper's argument for Q1S1 over Q0S2;
///   simplest:DB  the same, an order counting as within the margin unless its ln Z lies more than DB deciban
///                plus two standard errors of the difference below the best: an order is rejected only when
///                the evidence against it is both strong and resolved by the runs. Buffers order the orders
///                by parameter count too (1 + 2Q + 4S = 1 + 2·buffers), so this is Occam's choice among the
///                orders the evidence cannot tell apart. The default is simplest:10 (a factor 10, Jeffreys'
///                "strong").
#pragma once

#include "inference/evidence.hpp"  // deciban: the unit of the margins

#include <string>
#include <vector>

namespace admitgen {

class SelectionRule {
 public:
  /// Parses "best", "cheapest:DB" or "simplest:DB" with DB ≥ 0; throws InputError otherwise.
  static SelectionRule parse(const std::string& text);
  static SelectionRule best() { return SelectionRule(Kind::best, 0.0); }
  static SelectionRule simplest(double margin_db) { return SelectionRule(Kind::simplest, margin_db); }

  /// Index of the chosen order. log_z[i] and log_z_error[i] in nats; buffers[i] = Q + 2S.
  std::size_t select(const std::vector<double>& log_z, const std::vector<double>& log_z_error,
                     const std::vector<int>& buffers) const;
  /// e.g. "best evidence" or "cheapest within 10 dB of the best evidence".
  std::string describe() const;
  std::string spelling() const;  ///< as given on the command line

 private:
  enum class Kind { best, cheapest, simplest };
  SelectionRule(Kind kind, double margin_db) : kind_(kind), margin_db_(margin_db) {}
  Kind kind_;
  double margin_db_;
};

/// Standard errors of a difference of ln Z allowed by simplest:DB.
inline constexpr double kSimplestErrors = 2.0;

}  // namespace admitgen

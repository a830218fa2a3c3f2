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
///   target       the fewest buffers whose passive estimate meets the accuracy target (selection/accuracy_target.hpp),
///                ties broken by higher evidence; when no fitted order meets it, simplest:10 decides.
/// Every rule chooses among the usable orders only: within the per-node budget of buffers, and with evidence that
/// is determined (its independent runs agree: an order whose runs disagree has an ln Z no rule can rank).
#pragma once

#include "inference/evidence.hpp"  // deciban: the unit of the margins

#include <string>
#include <vector>

namespace admitgen {

class SelectionRule {
 public:
  /// Parses "best", "target", "cheapest:DB" or "simplest:DB" with DB ≥ 0; throws InputError otherwise.
  static SelectionRule parse(const std::string& text);
  static SelectionRule best() { return SelectionRule(Kind::best, 0.0); }
  static SelectionRule simplest(double margin_db) { return SelectionRule(Kind::simplest, margin_db); }
  static SelectionRule target() { return SelectionRule(Kind::target, 0.0); }

  /// Index of the chosen order. log_z[i] and log_z_error[i] in nats; buffers[i] = Q + 2S.
  std::size_t select(const std::vector<double>& log_z, const std::vector<double>& log_z_error,
                     const std::vector<int>& buffers) const;
  /// The same among the orders with usable[i] (at least one); meets[i]: order i's passive estimate meets the
  /// accuracy target (read by `target` only).
  std::size_t select(const std::vector<double>& log_z, const std::vector<double>& log_z_error,
                     const std::vector<int>& buffers, const std::vector<bool>& meets,
                     const std::vector<bool>& usable) const;
  bool uses_target() const { return kind_ == Kind::target; }
  /// e.g. "best evidence" or "cheapest within 10 dB of the best evidence".
  std::string describe() const;
  std::string spelling() const;  ///< as given on the command line

 private:
  enum class Kind { best, cheapest, simplest, target };
  SelectionRule(Kind kind, double margin_db) : kind_(kind), margin_db_(margin_db) {}
  Kind kind_;
  double margin_db_;
};

/// Standard errors of a difference of ln Z allowed by simplest:DB.
inline constexpr double kSimplestErrors = 2.0;
/// The margin (deciban) of the evidence rule `target` falls back on when no order meets the target.
inline constexpr double kTargetFallbackMarginDb = 10.0;

}  // namespace admitgen

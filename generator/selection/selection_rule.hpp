// SPDX-License-Identifier: MIT
/// @file
/// How an order is chosen from the evidence grid (docs/method.md, "Model selection"):
///   best         the highest ln Z;
///   cheapest:DB  the fewest state buffers (Q + 2S) among orders within DB deciban of the best
///                (ties broken by higher evidence) — the paper's argument for Q1S1 over Q0S2.
#pragma once

#include "inference/evidence.hpp"  // deciban: the unit of the cheapest:DB margin

#include <string>
#include <vector>

namespace admitgen {

class SelectionRule {
 public:
  /// Parses "best" or "cheapest:DB" with DB ≥ 0; throws InputError otherwise.
  static SelectionRule parse(const std::string& text);
  static SelectionRule best() { return SelectionRule(false, 0.0); }

  /// Index of the chosen order. log_z[i] in nats; buffers[i] = Q + 2S.
  std::size_t select(const std::vector<double>& log_z, const std::vector<int>& buffers) const;
  /// e.g. "best evidence" or "cheapest within 10 dB of the best evidence".
  std::string describe() const;
  std::string spelling() const;  ///< as given on the command line

 private:
  SelectionRule(bool cheapest, double margin_db) : cheapest_(cheapest), margin_db_(margin_db) {}
  bool cheapest_;
  double margin_db_;
};

}  // namespace admitgen

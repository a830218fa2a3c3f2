// SPDX-License-Identifier: MIT
/// @file
/// Uniform priors per parameter family (docs/method.md, paper Table 1) and the unit-cube transform that
/// nested sampling draws through, optionally in the symmetry-reduced space.
///
/// Symmetry reduction: the likelihood is invariant under (β_s, C_s) → (−β_s, −C_s) for each pair and
/// under any permutation of the real poles or of the pairs. The reduced space keeps one copy, the
/// canonical domain λ_1 ≤ … ≤ λ_Q, α_1 ≤ … ≤ α_S, β_s ≥ 0 (reports re-sort pairs by β, the
/// reported form, with fold_to_reduced). It holds
/// 1/(Q! S! 2^S) of the prior mass and its prior density is higher by that factor, so
/// Z = ∫ L π dθ is unchanged (L takes the same value on every copy).
/// The sampler reaches it by folding, not by a sorted transform: chains move in the full unit cube
/// (where the likelihood has no seams) and every accepted point is folded to its canonical copy.
/// Folding maps the uniform distribution on {L > L*} onto the uniform distribution on its canonical
/// part, so nested sampling's volume statistics hold unchanged. (A sorted/order-statistics transform
/// puts a seam where two poles would swap labels; chains cannot cross it and lose the better mode
/// when a broad and a sharp pair must trade places: Q0S2 on the reference file, Q0S3 on Basotect.)
#pragma once

#include "model/order.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace admitgen {

struct Range {
  double lo;
  double hi;
  double width() const { return hi - lo; }
};

struct PriorRanges {
  Range g_inf{-1.0, 1.0};
  Range a{-40000.0, 40000.0};
  Range lambda{0.0, 75000.0};
  Range b{-10000.0, 10000.0};
  Range c{-1000.0, 1000.0};
  Range alpha{0.0, 20000.0};
  Range beta{-15000.0, 15000.0};

  /// Paper Table 1 (s⁻¹; fits 0.1-4 kHz data).
  static PriorRanges table1() { return {}; }
  /// Table 1 overridden by a JSON file {"G_inf": [lo, hi], "A": [...], "lambda": [...], "B": [...],
  /// "C": [...], "alpha": [...], "beta": [...]} (any subset). Throws InputError naming the file and key.
  static PriorRanges from_file(const std::string& path);

  const Range& of(Family f) const;
  Range& of(Family f);
  /// Throws InputError unless every lo < hi and λ, α ranges start at ≥ 0 (causality).
  void validate(const std::string& origin) const;
  nlohmann::ordered_json to_json() const;
};

/// Maps u ∈ [0,1]^dim to θ under the priors (uniform, or uniform on the reduced space).
class PriorTransform {
 public:
  /// Reduction needs the β and C ranges symmetric about 0 (the fold (β, C) → (−β, −C) must map the
  /// prior onto itself); throws InputError otherwise.
  PriorTransform(const Order& order, const PriorRanges& ranges, bool reduce_symmetry);

  void operator()(const double* u, double* theta) const;
  /// Maps u to the u of the canonical copy (identity when not reduced): β ≥ 0 (u → 1 − u on β and C,
  /// whose ranges are symmetric), pairs by ascending α, real poles by ascending λ.
  void fold(double* u) const;
  const Order& order() const { return order_; }
  bool reduced() const { return reduced_; }

 private:
  Order order_;
  PriorRanges ranges_;
  bool reduced_;
};

/// Maps any θ to fit.json's reporting form (λ ascending; β ≥ 0 with C flipped alongside, pairs by
/// ascending β); applied to every run before it is summarised.
void fold_to_reduced(const Order& order, double* theta);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Priors per parameter family (docs/method.md, "Priors") and the unit-cube transform that nested sampling
/// draws through, optionally in the symmetry-reduced space. The poles are uniform over their ranges; the
/// linear parameters r = (G∞, A, B, C) are either zero-mean Gaussian, each term scaled to its own pole (the
/// default, ResiduePrior::gaussian), or uniform over the seed paper's Table 1 box (ResiduePrior::uniform).
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

#include <string>
#include <utility>
#include <vector>

namespace admitgen {

struct Range {
  double lo;
  double hi;
  double width() const { return hi - lo; }
};

/// How the linear parameters are distributed a priori (docs/method.md, "The Gaussian residue prior").
enum class ResiduePrior {
  /// r_k ~ N(0, s_k²) independently, s_k = s·(1 for G∞, λ_q for A_q, α_s for B_s and C_s): every term's
  /// contribution to G has the admittance scale s (PriorRanges::admittance_scale) whatever its pole.
  gaussian,
  /// r_k uniform over the ranges g_inf, a, b, c (the seed paper's Table 1).
  uniform,
};

/// The default admittance scale s of the Gaussian residue prior (normalised admittance; docs/method.md,
/// "The Gaussian residue prior", on why 1).
constexpr double kDefaultAdmittanceScale = 1.0;

struct PriorRanges {
  Range g_inf{-1.0, 1.0};
  Range a{-40000.0, 40000.0};
  Range lambda{0.0, 75000.0};
  Range b{-10000.0, 10000.0};
  Range c{-1000.0, 1000.0};
  Range alpha{0.0, 20000.0};
  Range beta{-15000.0, 15000.0};
  ResiduePrior residues = ResiduePrior::uniform;
  double admittance_scale = kDefaultAdmittanceScale;  ///< s of ResiduePrior::gaussian
  /// The pole ranges are those of `band` for the data's highest frequency, set when the data are known
  /// (selection/fit.hpp with_band_priors); until then those of the seed paper's 4 kHz band.
  bool band_of_data = false;

  /// Paper Table 1 (s⁻¹; fits 0.1-4 kHz data): every family uniform.
  static PriorRanges table1() { return {}; }
  /// The default: Gaussian residues of scale s, and pole ranges scaled to the data's highest angular frequency
  /// ω_max: λ, α ∈ [0, kBandPoleFactor·ω_max], β ∈ ±kBandResonanceFactor·ω_max (docs/method.md, "Pole ranges").
  static PriorRanges band(double omega_max, double admittance_scale = kDefaultAdmittanceScale);
  /// `band` for data not yet read: band_of_data set (the fit's default).
  static PriorRanges band_of_the_data(double admittance_scale = kDefaultAdmittanceScale);
  static constexpr double kBandPoleFactor = 4.0;
  static constexpr double kBandResonanceFactor = 2.0;

  const Range& of(Family f) const;
  Range& of(Family f);
  /// Throws InputError unless every lo < hi and λ, α ranges start at ≥ 0 (causality).
  void validate(const std::string& origin) const;
  /// (file key, range) of every family that has a range, in the prior file's key order (G_inf, A, lambda, B,
  /// C, alpha, beta); under the Gaussian residue prior only the poles' (lambda, alpha, beta).
  std::vector<std::pair<std::string, Range>> named() const;
  /// The range of the family with that prior-file key, nullptr for an unknown key (the prior file,
  /// io/priors_file.hpp, overrides Table 1 by these keys).
  Range* find(const std::string& key);
};

/// The prior standard deviation of every residue of θ's poles under ResiduePrior::gaussian, in
/// model/residue_basis.hpp order: s, s·λ_q, then s·α_s twice per pair. `poles` in inference/pole_space.hpp
/// packing (λ_1 … λ_Q, α_1, β_1, …).
void gaussian_residue_scales(const Order& order, const double* poles, double admittance_scale, double* sd);

/// Maps u ∈ [0,1]^dim to θ under the priors (or on the reduced space). Gaussian residues are
/// s_k(poles)·Φ⁻¹(u_k), so the fold's u → 1 − u still flips the sign of C.
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

// SPDX-License-Identifier: MIT
/// @file
/// Is structure left in a residual r_i = y_real(f_i) − y_model(f_i) along frequency? Under white noise
/// (independent points, Re and Im independent with equal variance) the lag-1 autocorrelation
///   ρ₁ = Σ_{i<N−1} Re(r_i conj r_{i+1}) / Σ_i |r_i|²
/// is a sum of 2(N − 1) products of independent terms, so ρ₁ ≈ N(0, 1/(2(N − 1))) and
///   z = ρ₁ √(2(N − 1))
/// is standard normal. A smooth unmodelled term makes neighbouring residuals alike: ρ₁ → 1, z ≫ 3.
/// The residual is called white when |z| < 3 (two-sided p ≈ 0.003). This is the lag-1 test of
/// docs/physics.md §5.0 step 3; it needs the points ordered in frequency, which they are.
#pragma once

#include <Eigen/Core>

namespace admitgen::diagnosis {

struct Whiteness {
  double lag1 = 0.0;  ///< ρ₁
  double z = 0.0;     ///< ρ₁ √(2(N − 1))
  bool white = true;  ///< |z| < kWhitenessZ

  static constexpr double kWhitenessZ = 3.0;
};

/// The lag-1 test of the residual (N ≥ 2; a zero residual is white).
Whiteness residual_whiteness(const Eigen::ArrayXcd& residual);

}  // namespace admitgen::diagnosis

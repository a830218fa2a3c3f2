// SPDX-License-Identifier: MIT
/// @file
/// The Student-t pieces the residue marginalisation needs (docs/method.md, "Residues given the
/// poles"): tails of the univariate t, chi-square draws, and draws of a univariate t truncated to an
/// interval. Distribution functions come from Boost.Math; every random draw goes through core/rng.hpp,
/// so a seed gives the same draws on every platform.
#pragma once

#include "core/rng.hpp"

#include <vector>

namespace admitgen {

/// Upper tail P(T > z) of the standard Student t with ν degrees of freedom. Tails below 1e-300 are 0.
double student_t_upper_tail(double nu, double z);

/// Standard t value z with P(T > z) = 1e-16 for ν degrees of freedom: beyond it a tail is below any
/// mass this code resolves, and student_t_upper_tail need not be called (it is the cost of a call).
double student_t_negligible_tail(double nu);

/// The upper tail of t_ν on [0, z_neg) (z_neg = student_t_negligible_tail(ν)) by cubic Hermite
/// interpolation of ln P(T > z) on a grid of step 1/64, with the exact values and slopes
/// d ln Q/dz = −f(z)/Q(z) at the nodes (Boost at construction). Interpolation error: h⁴/384 ·
/// max|d⁴ ln Q/dz⁴| ≲ 1e-10 relative (ln Q is within a few % of a quadratic for ν ≥ 30); beyond
/// z_neg the tail is 0 (below 1e-16). For z_neg > 64 (ν ≲ 10: a handful of data) every call goes
/// to Boost.
class StudentTail {
 public:
  explicit StudentTail(double nu);
  double upper(double z) const;  ///< P(T > z), z ≥ 0
  /// An upper bound of ln P(T > z) that stays finite where P underflows: ln of the exact tail below
  /// z_neg, beyond it ln[f(z)(ν + z²)/((ν − 1) z)] (f the t density), which exceeds the tail by a factor
  /// at most ν(1 + 1/z²)/(ν − 1) (integrate its derivative, −f ν(1 + 1/z²)/(ν − 1) ≤ −f).
  double log_upper_bound(double z) const;
  double negligible() const { return z_neg_; }

 private:
  double nu_, z_neg_, step_ = 1.0 / 64.0;
  double log_density_constant_;  ///< ln Γ((ν+1)/2) − ln Γ(ν/2) − ½ ln(νπ)
  std::vector<double> log_q_, slope_;
};

/// A chi-square draw with ν degrees of freedom: 2·Gamma(ν/2), Gamma by Marsaglia & Tsang (2000),
/// exact rejection (shape a < 1 as Gamma(a + 1)·U^{1/a}).
double chi_square_draw(double nu, Rng& rng);

/// A standard t (ν degrees of freedom) draw conditioned on a ≤ T ≤ b, by inversion of the CDF on the
/// side of the interval with the larger tail-free precision (the interval is mirrored to the left of
/// 0 when it lies right of it, so probabilities near 1 are never subtracted).
double truncated_student_t_draw(double nu, double a, double b, Rng& rng);

}  // namespace admitgen

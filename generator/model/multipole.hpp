// SPDX-License-Identifier: MIT
/// @file
/// Evaluation of the multipole admittance (docs/method.md; paper eq. 2-3), e^{+jωt}:
///   G(ω) = G∞ + Σ_q A_q/(λ_q + jω) + Σ_s [Θ_s/(θ_s + jω) + Θ_s*/(θ_s* + jω)],
///   Θ_s = B_s + jC_s, θ_s = α_s + jβ_s.
/// One code path for every order: the loops run over terms, each term is whole-array arithmetic on
/// the frequency grid (Eigen arrays vectorise it), and there is no per-order special case.
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>

namespace admitgen {

/// Frequency grid plus scratch space, so that repeated evaluation allocates nothing.
class MultipoleGrid {
 public:
  explicit MultipoleGrid(const Eigen::ArrayXd& omega);
  const Eigen::ArrayXd& omega() const { return omega_; }

  /// Real and imaginary parts of G at the grid, written into re, im (resized if needed).
  /// Term algebra, with d = λ² + ω², d± = α² + (ω ± β)²:
  ///   A/(λ + jω) = A(λ − jω)/d
  ///   (B + jC)/(α + j(ω + β)) = [Bα + C(ω + β) + j(Cα − B(ω + β))]/d+
  ///   (B − jC)/(α + j(ω − β)) = [Bα − C(ω − β) − j(Cα + B(ω − β))]/d−
  /// A pair costs one division: 1/d+ = d−/(d+ d−) and 1/d− = d+/(d+ d−) (d± ≤ ~1e11 for audio-band
  /// ω and Table 1 ranges, so the product stays far from overflow).
  void evaluate(const Order& order, const double* theta, Eigen::ArrayXd& re, Eigen::ArrayXd& im) const;

 private:
  Eigen::ArrayXd omega_, omega2_;
  mutable Eigen::ArrayXd dp_, dm_, inv_;
};

/// One-off evaluation (allocates a grid); θ packed as model/order.hpp.
void evaluate_multipole(const Order& order, const double* theta, const Eigen::ArrayXd& omega,
                        Eigen::ArrayXd& re, Eigen::ArrayXd& im);

/// Convenience form returning G as complex values.
Eigen::ArrayXcd evaluate_multipole(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega);

/// Conditioning of a model over frequencies ω (docs/passivity.md, "Conditioning"): the largest sum of the
/// terms' magnitudes, |G∞| + Σ|A_q/(λ_q + jω)| + Σ|pair_s(ω)| (a pair and its conjugate as one term), over the
/// largest |G|. 1 when no terms cancel; 679 for a model whose cancelling dipoles are 679× max |G|. A
/// fixed-point table's shared exponent is set by the terms, so log2 of it is the bits lost to cancellation.
double term_conditioning(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega);

}  // namespace admitgen

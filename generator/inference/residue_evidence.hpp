// SPDX-License-Identifier: MIT
/// @file
/// The likelihood of the poles alone under the Gaussian residue prior, the residues and the noise
/// integrated out exactly (docs/method.md, "The closed-form marginal", which derives every formula here).
///
/// For poles ψ the model is G = Φ r (model/residue_basis.hpp). Stacking real and imaginary parts, A = [Re Φ;
/// Im Φ] (2N × p), b = [Re D; Im D]. With r ~ N(0, Σ₀), Σ₀ = D² (D = diag of gaussian_residue_scales,
/// inference/priors.hpp), and the noise N(0, σ² I) on each of the K real data,
///   p(b | ψ, σ) = N(b; 0, σ² I + A Σ₀ Aᵀ).
/// With M̃ = D AᵀA D = V diag(μ_k) Vᵀ (one symmetric eigendecomposition per ψ), h = Vᵀ D Aᵀb, c_k² = h_k²/μ_k and
/// S₀ = |b|² − Σ c_k² (the least-squares residual), in t = ln σ² (v = e^t):
///   ln p(b | ψ, σ) = −(K/2)(ln 2π + t) − ½ Σ ln(1 + μ_k/v) − ½ S₀/v − ½ Σ c_k²/(μ_k + v),
/// each σ costing O(p). σ keeps the Jeffreys prior dσ/σ = dt/2 of inference/likelihood.hpp, and
///   L(ψ) = ∫ ½ p(b | ψ, e^{t/2}) dt
/// is found by Gauss-Hermite quadrature around the mode of the integrand in t (Newton), or by adaptive
/// Gauss-Kronrod (Boost.Math) where the integrand is far from Gaussian (few data per residue).
#pragma once

#include "core/rng.hpp"
#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/residue_gram.hpp"
#include "model/order.hpp"
#include "numerics/eigen_projection.hpp"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <vector>

namespace admitgen {

/// Everything about r and σ given the poles ψ.
struct ResiduePosterior {
  bool valid = false;          ///< false for poles outside the model's domain (λ, α ≤ 0) or non-finite sums
  Eigen::VectorXd sd;          ///< D: the prior standard deviations of r
  Eigen::VectorXd mu;          ///< eigenvalues μ_k of M̃ = D AᵀA D (ascending, ≥ 0; numerically null ones 0)
  Eigen::MatrixXd v;           ///< its eigenvectors (columns)
  Eigen::VectorXd h;           ///< Vᵀ D Aᵀb
  Eigen::VectorXd c2;          ///< c_k² = h_k²/μ_k (0 where μ_k = 0)
  double s0 = 0.0;             ///< S₀ = |b|² − Σ c_k², floored at 1e-300
  double k = 0.0;              ///< K, the number of real data
  double t_mode = 0.0;         ///< the mode t* of the integrand over t = ln σ²
  double t_scale = 0.0;        ///< 1/√(−f''(t*)): the Laplace width in t
  double log_evidence = 0.0;   ///< ln L(ψ): r and σ integrated out
};

/// ln ½ p(b | ψ, σ² = e^t) (the integrand over t; docs/method.md, "The closed-form marginal").
double residue_log_integrand(const ResiduePosterior& c, double t);

/// Gauss-Hermite nodes of the σ integral; where ν = K − p is below kMinGaussHermiteNu the adaptive
/// Gauss-Kronrod rule runs instead (both within 0.01 nats of brute force, tests/inference/test_residue_evidence.cpp).
/// 10 nodes: on the integrand with no residues, ∫ e^{−νt/2 − S e^{−t}/2} dt = Γ(ν/2)(S/2)^{−ν/2} in closed
/// form, the rule's error is 1.6e-7 nats at ν = 40, 4e-9 at ν = 100 and below 1e-11 from ν = 400 (16 nodes:
/// 7e-10 at ν = 40), docs/method.md "The closed-form marginal".
constexpr int kGaussHermiteNodes = 10;
constexpr double kMinGaussHermiteNu = 40.0;

/// Holds data and work buffers: one instance per thread.
class ResidueEvidence {
 public:
  ResidueEvidence(const Measurement& data, const Order& order, DataCount count, double admittance_scale);

  /// ln L(ψ) (inference/pole_space.hpp packing; nullptr for Q0S0), without the eigenvectors of M̃: the
  /// sampler's call. It equals posterior(poles).log_evidence to rounding (about 1e-13 relative).
  double operator()(const double* poles) const;
  /// The conditional of r and σ at ψ, eigenvectors included (valid until the next call).
  const ResiduePosterior& posterior(const double* poles) const;

  const Order& order() const { return order_; }
  int k() const { return k_; }

 private:
  Order order_;
  GramPoints points_;
  double b_norm2_;
  int k_, p_;
  double scale_;
  mutable Eigen::MatrixXd m_;
  mutable Eigen::VectorXd g_, y_;  // y = D g
  mutable Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen_;
  mutable numerics::EigenProjection projection_;
  mutable ResiduePosterior c_;

  /// M̃ and D into m_ and c_.sd at ψ; false (c_ invalid) outside the domain or for non-finite sums.
  bool gram(const double* poles) const;
  /// S₀, c², the mode in t and ln L(ψ) from c.mu and c.h.
  const ResiduePosterior& integrate(ResiduePosterior& c) const;
};

/// ln ∫ exp(f(t)) dt of the posterior's integrand (the quadrature behind log_evidence, exposed for tests).
double integrate_noise(const ResiduePosterior& c);

/// One exact draw of (σ², r) from their posterior given ψ: t = ln σ² by inversion of its tabulated CDF
/// (kNoiseGridPoints over ±kNoiseGridWidths Laplace widths), then r | σ² Gaussian,
/// r = D V z, z_k ~ N(h_k/(μ_k + v), v/(μ_k + v)). `sigma2` receives σ² when not null.
Eigen::VectorXd draw_residues(const ResiduePosterior& c, Rng& rng, double* sigma2 = nullptr);
constexpr int kNoiseGridPoints = 512;
constexpr double kNoiseGridWidths = 12.0;

/// The least-squares residues r̂ = D V diag(1/μ_k) h (the null directions of M̃ left at 0): the best fit at ψ.
Eigen::VectorXd least_squares_residues(const ResiduePosterior& c);

}  // namespace admitgen

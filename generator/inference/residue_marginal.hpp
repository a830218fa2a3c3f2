// SPDX-License-Identifier: MIT
/// @file
/// The likelihood of the poles alone, the residues integrated out analytically (docs/method.md,
/// "Residues given the poles", which derives every formula here).
///
/// For poles ψ the model is G = Φ r (model/residue_basis.hpp). Stacking real and imaginary parts,
/// A = [Re Φ; Im Φ] (2N × p), b = [Re D; Im D]:
///   Σ|D − G|² = |b − A r|² = S_min + (r − r̂)ᵀ M (r − r̂),   M = AᵀA = ReΦᵀReΦ + ImΦᵀImΦ,  r̂ = M⁻¹Aᵀb,
/// so L(ψ, r) ∝ S(r)^{−K/2} is, in r, a multivariate Student t with ν = K − p degrees of freedom,
/// location r̂ and scale matrix S_min/ν · M⁻¹, and
///   (1/V_r) ∫_box L dr = P_box · Γ(ν/2)/2 · π^{−ν/2} S_min^{−ν/2} det(M)^{−1/2} / V_r,
/// P_box being the t's mass inside the residue box (V_r its volume). P_box is bounded by its
/// coordinate marginals (exact univariate t intervals):
///   P_lo = max(0, 1 − Σ_k (1 − P_k)) ≤ P_box ≤ P_up = min_k P_k,
/// with further upper bounds along the eigen-directions of the box-scaled covariance; the sampler uses P̃,
/// their product averaged over the t's scale (docs/method.md, "The box mass the sampler uses"), clamped to
/// [P_lo, P_up], and the pole sampler reweights by P̂/P̃ (inference/poles_sampler.hpp).
#pragma once

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/priors.hpp"
#include "inference/residue_gram.hpp"
#include "inference/student_t.hpp"
#include "model/order.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <vector>

namespace admitgen {

/// The conditional posterior of r for one set of poles.
struct ResidueConditional {
  bool valid = false;          ///< false when M is numerically singular (then ln L = −∞)
  Eigen::VectorXd mean;        ///< r̂
  Eigen::VectorXd scale;       ///< D = diag(M)^{−1/2}: M = D⁻¹ M̃ D⁻¹
  Eigen::MatrixXd chol;        ///< lower Cholesky factor L̃ of M̃ = D M D
  Eigen::MatrixXd m;           ///< M itself (for Gibbs conditionals)
  double s_min = 0.0;          ///< S_min = min_r Σ|D − G|²
  double nu = 0.0;             ///< K − p
  double k = 0.0;              ///< K
  double log_p_up = 0.0;       ///< ln P_up
  double log_p_lo = 0.0;       ///< ln P_lo (−∞ when the union bound gives 0)
  double log_p_sampled = 0.0;  ///< ln P̃, P_lo ≤ P̃ ≤ P_up: the product of the eigen-direction bounds
  double log_untruncated = 0.0;  ///< ln[(1/V_r) ∫ L dr] over all of r (P_box = 1)
  double log_marginal = 0.0;   ///< ln[(1/V_r) ∫ L dr] with P̃ in place of P_box (untruncated(): P_box = 1)
};

/// The normal equations are trusted while |ŷ|₁ ≤ this × |b| (ŷ = D⁻¹r̂, each term's share of the fit in the
/// data's norm): the rounding of S_min = |b|² − ŷᵀM̃ŷ then stays near that of |b|² itself. Beyond it the
/// terms cancel each other and S_min comes from a QR factorisation (docs/method.md, "Accuracy of the normal
/// equations").
constexpr double kNormalEquationsGrowth = 10.0;
/// ln L may be off by at most this many nats through the rounding of S_min (ν/2 · δS/S ≤ this): otherwise ψ
/// is left out.
constexpr double kSminLogTolerance = 0.01;

/// Holds data, basis and work buffers: one instance per thread.
class ResidueMarginal {
 public:
  ResidueMarginal(const Measurement& data, const Order& order, DataCount count, const PriorRanges& ranges);

  /// ln of the residue-marginal likelihood at poles ψ (inference/pole_space.hpp packing).
  double operator()(const double* poles) const;
  /// Everything about r given ψ.
  const ResidueConditional& conditional(const double* poles) const;
  /// The same without the box: r̂, M, S_min and log_marginal = log_untruncated (the bounds stay 0). For
  /// the sampler that integrates the box mass by its own coordinates (inference/poles_sampler.hpp).
  const ResidueConditional& untruncated(const double* poles) const;
  /// Fills A = [Re Φ; Im Φ] (2N × p) at ψ: model/residue_basis.hpp's columns, vectorised over ω.
  void fill_basis(const double* poles, Eigen::MatrixXd& a) const;

  const Eigen::VectorXd& box_lo() const { return lo_; }
  const Eigen::VectorXd& box_hi() const { return hi_; }
  const Order& order() const { return order_; }
  int k() const { return k_; }

 private:
  Order order_;
  Eigen::ArrayXd omega_, omega2_;
  GramPoints points_;
  mutable std::vector<double> gram_work_;
  Eigen::VectorXd b_;
  double b_norm2_;
  int k_, p_;
  StudentTail tail_;  ///< t_ν tails, ν = K − p
  double constant_;    ///< ln Γ(ν/2) − ln 2 − (ν/2) ln π − ln V_r
  Eigen::VectorXd lo_, hi_;
  mutable Eigen::MatrixXd a_, inv_chol_, scaled_;
  mutable Eigen::VectorXd g_, mean_scaled_, v_;
  Eigen::ArrayXd width_;
  mutable Eigen::LLT<Eigen::MatrixXd> llt_;
  /// ln E_W[Π_j P(slab_j | W)] over the cut slabs (slab_lo_/slab_hi_ in units of the t scale).
  double log_slab_mixture() const;
  double mixture_log_norm_ = 0.0;             ///< ln[(ν/2)^{ν/2}/Γ(ν/2)]
  mutable std::vector<double> mixture_terms_;  ///< ln of the quadrature terms over ln(W/ν)
  mutable std::vector<int> cut_slabs_;         ///< the slabs holding less than 1 − 1e-12 of the t
  mutable Eigen::MatrixXd directions_;         ///< slab directions v in r (columns)
  mutable Eigen::ArrayXd slab_lo_, slab_hi_;
  mutable Eigen::MatrixXd box_cov_;
  mutable Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen_;
  mutable Eigen::ArrayXd dp_, dm_, inv_;
  mutable Eigen::MatrixXd m_scaled_;         ///< M̃ for the box-constrained minimum
  mutable Eigen::VectorXd box_a_, box_b_;  ///< the box in Jacobi-scaled coordinates
  mutable ResidueConditional c_;
  /// Fills c_ up to log_untruncated; false when M is numerically singular.
  bool solve(const double* poles) const;
  /// solve()'s path where the normal equations cannot give S_min to the tolerance: QR of the basis.
  bool solve_by_qr(const double* poles) const;
  mutable Eigen::HouseholderQR<Eigen::MatrixXd> qr_;
};

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The eigenvalues of a small symmetric matrix A = V diag(μ) Vᵀ together with the projections h = Vᵀ y of one
/// vector y on its eigenvectors, without forming V (docs/method.md, "The closed-form marginal": the residue
/// marginal needs μ and h at every likelihood call, V only when residues are drawn).
///
/// Method (Golub & Van Loan, *Matrix Computations*, 4th ed., §8.3): Householder tridiagonalisation
/// A = Q T Qᵀ (Eigen's Tridiagonalization, whose reflectors are applied to y as Qᵀ y without forming Q), then
/// implicit symmetric QR steps with the Wilkinson shift on T (Algorithm 8.3.2) and deflation of negligible
/// off-diagonal entries (§8.3.5). Each Givens rotation R of a step is applied to the vector w = Qᵀ y alone
/// instead of being accumulated into the eigenvector matrix: at convergence P T Pᵀ = diag(μ) for the
/// product P of the rotations, so V = Q Pᵀ and h = P Qᵀ y. This is the idea of Golub & Welsch (1969), who
/// carry only the first row of the eigenvectors to get Gauss quadrature weights; here it saves the O(p³)
/// accumulation, most of a full eigendecomposition's cost at p ≤ 25.
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

namespace admitgen::numerics {

/// Reusable work space: one per thread; compute() allocates only when the size grows.
class EigenProjection {
 public:
  /// μ (ascending) and h = Vᵀ y of the symmetric `a` (its lower triangle is read). false when the QR
  /// iteration did not converge within 30 sweeps per eigenvalue (the results are then undefined).
  bool compute(const Eigen::MatrixXd& a, const Eigen::VectorXd& y);

  const Eigen::VectorXd& eigenvalues() const { return mu_; }
  const Eigen::VectorXd& projections() const { return h_; }

 private:
  Eigen::Tridiagonalization<Eigen::MatrixXd> tri_;
  Eigen::MatrixXd scaled_;
  Eigen::VectorXd mu_, h_, sub_;
};

}  // namespace admitgen::numerics

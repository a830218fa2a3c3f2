// SPDX-License-Identifier: MIT
// Eigenvalues and eigenvector projections without the eigenvectors (numerics/eigen_projection.hpp) against
// Eigen's SelfAdjointEigenSolver, an independent implementation (it accumulates the eigenvectors). The
// projections h_k are compared through quantities that do not depend on the eigenvectors' signs or on the
// basis chosen inside a repeated eigenvalue's eigenspace: Σ h_k² /(μ_k + v) = yᵀ (A + vI)⁻¹ y for several
// v > 0, solved by Cholesky, and Σ h_k² = |y|².
#include "core/rng.hpp"
#include "numerics/eigen_projection.hpp"
#include "test_support.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace admitgen;
using test::random_matrix;
using numerics::EigenProjection;

namespace {

/// Checks one matrix. A backward-stable symmetric eigensolver (both are: Householder plus orthogonal
/// rotations) returns eigenvalues within c·n·ε·‖A‖₂ of the exact ones (Golub & Van Loan, Thm 8.3.x, with c a
/// small constant); 20 n ε ‖A‖ for each of the two solvers bounds their difference. The resolvent form
/// yᵀ(A + vI)⁻¹y with v ≥ 1.5 ‖A‖ is conditioned by at most 5, so 1e-12 relative covers it.
void check(const Eigen::MatrixXd& a, const Eigen::VectorXd& y) {
  const Eigen::Index n = a.rows();
  EigenProjection projection;
  REQUIRE(projection.compute(a, y));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(a);
  const double norm = reference.eigenvalues().cwiseAbs().maxCoeff();
  const double eps = std::numeric_limits<double>::epsilon();
  const Eigen::VectorXd& mu = projection.eigenvalues();
  const Eigen::VectorXd& h = projection.projections();
  for (Eigen::Index k = 0; k < n; ++k) {
    CHECK(std::abs(mu[k] - reference.eigenvalues()[k]) <= 40.0 * static_cast<double>(n) * eps * std::max(norm, 1e-300));
    if (k > 0) CHECK(mu[k] >= mu[k - 1]);
  }
  CHECK(std::abs(h.squaredNorm() - y.squaredNorm()) <= 1e-13 * y.squaredNorm());
  for (double v : {1.5 * norm, 3.0 * norm, 10.0 * norm}) {  // A + vI positive definite even for indefinite A
    const Eigen::MatrixXd shifted = a + v * Eigen::MatrixXd::Identity(n, n);
    const double exact = y.dot(shifted.llt().solve(y));
    double from_projection = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) from_projection += h[k] * h[k] / (mu[k] + v);
    CHECK(std::abs(from_projection - exact) <= 1e-12 * std::abs(exact));
  }
}

}  // namespace

TEST_CASE("eigen projection: random symmetric matrices of every size up to 25") {
  Rng rng(20261127);
  for (Eigen::Index n = 1; n <= 25; ++n) {
    const Eigen::MatrixXd b = random_matrix(rng, n, n);
    check(b + b.transpose(), random_matrix(rng, n, 1));
  }
}

TEST_CASE("eigen projection: Gram matrices of rank k < n, with repeated zero eigenvalues") {
  Rng rng(7);
  for (Eigen::Index n : {2, 5, 13, 21})
    for (Eigen::Index k : {Eigen::Index{1}, n / 2, n - 1}) {
      const Eigen::MatrixXd b = random_matrix(rng, n, k);
      check(b * b.transpose(), random_matrix(rng, n, 1));
    }
}

TEST_CASE("eigen projection: badly scaled and already diagonal matrices") {
  Rng rng(3);
  // Scales over 24 decades, as a residue Gram matrix in prior units can have.
  Eigen::VectorXd scale(9);
  for (Eigen::Index i = 0; i < 9; ++i) scale[i] = std::pow(10.0, 3.0 * static_cast<double>(i) - 12.0);
  const Eigen::MatrixXd b = random_matrix(rng, 9, 12);
  const Eigen::MatrixXd gram = scale.asDiagonal() * (b * b.transpose()) * scale.asDiagonal();
  check(gram, random_matrix(rng, 9, 1));
  // Diagonal: no rotation at all; the eigenvalues sorted and h permuted with them.
  Eigen::MatrixXd diag = Eigen::MatrixXd::Zero(4, 4);
  diag.diagonal() << 3.0, -1.0, 2.0, 0.5;
  Eigen::VectorXd y(4);
  y << 1.0, 2.0, 3.0, 4.0;
  EigenProjection projection;
  REQUIRE(projection.compute(diag, y));
  CHECK(projection.eigenvalues() == Eigen::Vector4d(-1.0, 0.5, 2.0, 3.0));
  CHECK(projection.projections().cwiseAbs() == Eigen::Vector4d(2.0, 4.0, 3.0, 1.0));
}

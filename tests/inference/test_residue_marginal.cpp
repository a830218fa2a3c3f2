// SPDX-License-Identifier: MIT
// The residue-marginal likelihood (inference/residue_marginal.hpp, docs/method.md "Residues given the
// poles") against independent references: the basis against model/residue_basis.hpp, and the closed
// form of (1/V_r) ∫_box L dr against a direct Gauss-Legendre quadrature of the full likelihood over r.
#include "inference/likelihood.hpp"
#include "inference/pole_space.hpp"
#include "inference/residue_gram.hpp"
#include "inference/residue_marginal.hpp"
#include "model/residue_basis.hpp"
#include "synthetic_data.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

/// Composite Gauss-Legendre rule on [lo, hi]: `panels` panels of 16 nodes (Golub-Welsch).
void rule(double lo, double hi, int panels, std::vector<double>& x, std::vector<double>& w) {
  constexpr int m = 16;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m, m);
  for (int k = 1; k < m; ++k) j(k, k - 1) = j(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(j);
  x.clear();
  w.clear();
  const double h = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p)
    for (int k = 0; k < m; ++k) {
      x.push_back(lo + h * (p + 0.5 * (es.eigenvalues()[k] + 1.0)));
      w.push_back(0.5 * h * 2.0 * es.eigenvectors()(0, k) * es.eigenvectors()(0, k));
    }
}

double log_sum_exp(const std::vector<double>& v) {
  double m = -INFINITY;
  for (double x : v) m = std::max(m, x);
  double s = 0.0;
  for (double x : v) s += std::exp(x - m);
  return m + std::log(s);
}

}  // namespace

TEST_CASE("residue marginal: basis columns equal model/residue_basis.hpp") {
  const Order o(2, 2);
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(o.dim());
  theta[Order::lambda(0)] = 900.0;
  theta[Order::lambda(1)] = 52000.0;
  theta[o.alpha(0)] = 1500.0;
  theta[o.beta(0)] = 10000.0;
  theta[o.alpha(1)] = 300.0;
  theta[o.beta(1)] = -2500.0;
  const Measurement data = test::synthetic(Order(0, 0), Eigen::VectorXd::Constant(1, 0.3), 40, 20.0, 6000.0, 0.01, 3);
  const ResidueMarginal marginal(data, o, DataCount::two_per_point, PriorRanges::table1());
  std::vector<double> poles;
  for (int i : pole_indices(o)) poles.push_back(theta[i]);
  Eigen::MatrixXd a;
  marginal.fill_basis(poles.data(), a);
  const ResidueBasis ref = residue_basis(o, theta, data.omega());
  const Eigen::Index n = data.size();
  // Same algebra in another arrangement: agreement to rounding (1e-12 relative to the column scale).
  for (Eigen::Index k = 0; k < a.cols(); ++k) {
    const double scale = ref.re.col(k).cwiseAbs().maxCoeff() + ref.im.col(k).cwiseAbs().maxCoeff();
    CHECK((a.col(k).head(n) - ref.re.col(k)).cwiseAbs().maxCoeff() <= 1e-12 * scale);
    CHECK((a.col(k).tail(n) - ref.im.col(k)).cwiseAbs().maxCoeff() <= 1e-12 * scale);
  }
}

TEST_CASE("residue gram: the fused pass equals AᵀA and Aᵀb from residue_basis.hpp (Q3S3 at 37, 43 and 8 points)") {
  // Points 37 and 43 (5 and 3 lanes of padding in the last block of 8) and 8 (none); every order term.
  const Order o(3, 3);
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(o.dim());
  const double lambdas[] = {900.0, 52000.0, 7000.0};
  for (int q = 0; q < 3; ++q) theta[Order::lambda(q)] = lambdas[q];
  const double pairs[][2] = {{1500.0, 10000.0}, {300.0, -2500.0}, {9000.0, 300.0}};
  for (int s = 0; s < 3; ++s) theta[o.alpha(s)] = pairs[s][0], theta[o.beta(s)] = pairs[s][1];
  std::vector<double> poles;
  for (int i : pole_indices(o)) poles.push_back(theta[i]);
  for (const int points : {37, 43, 8}) {
    const Measurement data = test::synthetic(Order(0, 0), Eigen::VectorXd::Constant(1, 0.3), points, 20.0, 6000.0, 0.01, 3);
    const ResidueBasis basis = residue_basis(o, theta, data.omega());
    const Eigen::MatrixXd m_ref = basis.re.transpose() * basis.re + basis.im.transpose() * basis.im;
    const Eigen::VectorXd g_ref = basis.re.transpose() * data.y.real().matrix() + basis.im.transpose() * data.y.imag().matrix();
    const GramPoints pts(data.omega(), data.y);
    const int p = residue_count(o);
    std::vector<double> work(residue_gram_work_size(p));
    Eigen::MatrixXd m(p, p);
    Eigen::VectorXd g(p);
    residue_gram(pts, o.q(), o.s(), poles.data(), work.data(), m.data(), g.data());
    // Sums of N products in another order: agreement to N·ε relative to Σ|products| (Cauchy-Schwarz bound
    // √(M_jj M_kk) for M, |φ_j|·|b| for g).
    const double tol = 4.0 * points * std::numeric_limits<double>::epsilon();
    for (int j = 0; j < p; ++j) {
      for (int k = 0; k < p; ++k)
        CHECK(std::abs(m(j, k) - m_ref(j, k)) <= tol * std::sqrt(m_ref(j, j) * m_ref(k, k)));
      CHECK(std::abs(g[j] - g_ref[j]) <= tol * std::sqrt(m_ref(j, j)) * std::sqrt(data.y.abs2().sum()));
    }
  }
  MESSAGE("residue_gram runs with ", residue_gram_isa());
}

TEST_CASE("residue marginal: closed form equals quadrature over r (1 residue truncated, 2 residues inside)") {
  // Data: Q1S0 truth (G∞ = 0.3, A = 5000 s⁻¹, λ = 8000 s⁻¹), 24 points 100-4000 Hz, σ = 0.05, seed 11.
  Eigen::VectorXd truth(3);
  truth << 0.3, 5000.0, 8000.0;
  const Measurement data = test::synthetic(Order(1, 0), truth, 24, 100.0, 4000.0, 0.05, 11);
  std::vector<double> x0, w0, x1, w1;

  SUBCASE("Q0S0, G∞ box cutting the conditional posterior (P_box exact for one residue)") {
    const Order o(0, 0);
    PriorRanges pr;
    const Likelihood like(data, o, DataCount::two_per_point);
    const ResidueMarginal marginal(data, o, DataCount::two_per_point, pr);
    const double centre = marginal.conditional(nullptr).mean[0];
    for (const double hi : {10.0, centre + 0.01, centre}) {
      pr.g_inf = {-1.0, hi};
      const ResidueMarginal cut(data, o, DataCount::two_per_point, pr);
      rule(pr.g_inf.lo, pr.g_inf.hi, 400, x0, w0);
      std::vector<double> terms;
      for (std::size_t i = 0; i < x0.size(); ++i) terms.push_back(std::log(w0[i] / pr.g_inf.width()) + like(&x0[i]));
      const double ref = log_sum_exp(terms);
      INFO("hi ", hi, ": quadrature ", ref, ", closed form ", cut(nullptr));
      // 6400 nodes on a smooth integrand of width ~0.01 over [−1, hi]: ≥ 60 nodes per posterior width.
      CHECK(std::abs(cut(nullptr) - ref) <= 1e-6);
    }
  }

  SUBCASE("Q1S0 with λ fixed: two residues, box far wider than the posterior") {
    const Order o(1, 0);
    PriorRanges pr;
    pr.g_inf = {-1.0, 1.5};
    pr.a = {-5000.0, 20000.0};
    const Likelihood like(data, o, DataCount::two_per_point);
    const ResidueMarginal marginal(data, o, DataCount::two_per_point, pr);
    const double lambda = 8000.0;
    const ResidueConditional& c = marginal.conditional(&lambda);
    const double closed = c.log_marginal;
    CHECK(c.log_p_up > -1e-12);  // deep inside: no truncation
    // Quadrature on ±12 conditional standard deviations around r̂ (the integrand beyond is < e^-60 of
    // the peak), times the box's prior density 1/V_r.
    const Eigen::MatrixXd cov = (c.scale.asDiagonal() * (c.chol * c.chol.transpose()).inverse() *
                                 c.scale.asDiagonal()) * (c.s_min / c.nu);
    const double s0 = std::sqrt(cov(0, 0)), s1 = std::sqrt(cov(1, 1));
    const auto integrate = [&](int panels) {
      rule(c.mean[0] - 12 * s0, c.mean[0] + 12 * s0, panels, x0, w0);
      rule(c.mean[1] - 12 * s1, c.mean[1] + 12 * s1, panels, x1, w1);
      std::vector<double> terms;
      for (std::size_t i = 0; i < x0.size(); ++i)
        for (std::size_t k = 0; k < x1.size(); ++k) {
          const double th[3] = {x0[i], x1[k], lambda};
          terms.push_back(std::log(w0[i] * w1[k]) + like(th));
        }
      return log_sum_exp(terms) - std::log(pr.g_inf.width() * pr.a.width());
    };
    const double fine = integrate(24), coarse = integrate(16);
    REQUIRE(std::abs(fine - coarse) < 1e-8);
    INFO("quadrature ", fine, ", closed form ", closed);
    CHECK(std::abs(closed - fine) <= 1e-6);
  }
}

TEST_CASE("residue marginal: S_min and det M of nearly coincident poles equal a long-double SVD") {
  // Q2S1 with λ₂ = λ₁(1 + δ): the two real-pole columns differ by O(δ), the least-squares residues grow
  // like 1/δ with opposite signs, and S_min = |b|² − ŷᵀM̃ŷ from the normal equations loses every digit
  // (at δ = 1e-4 it came out 12× too small: +490 nats of ln L). Reference: one-sided Jacobi SVD of the
  // same basis in long double (64-bit mantissa, ε = 5.4e-20), S_ref from its explicit residual and
  // ln det M_ref = 2 Σ ln σ_i. Tolerances: ν/2 · |δS|/S ≤ 0.01 nats (kSminLogTolerance) and ln det M
  // within 0.01 (the QR pivots carry relative error ε·cond(A) ≤ 1e-3 where the marginal accepts them).
  // ψ is allowed to come out invalid only where cond(A) > 1e9 (there the bound of solve_by_qr may refuse).
  Eigen::VectorXd truth(7);
  truth << 0.3, 5000.0, 8000.0, 400.0, -150.0, 1500.0, 9000.0;
  const Measurement data = test::synthetic(Order(1, 1), truth, 200, 100.0, 4000.0, 0.01, 17);
  const Order o(2, 1);
  const ResidueMarginal marginal(data, o, DataCount::two_per_point, PriorRanges::table1());
  using MatrixL = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;
  using VectorL = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  const Eigen::Index n = data.size();
  VectorL b(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = data.y[i].real(), b[n + i] = data.y[i].imag();
  int accepted_cancelling = 0;
  for (const double delta : {1e-1, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8}) {
    const std::vector<double> poles{8000.0, 8000.0 * (1.0 + delta), 1500.0, 9000.0};
    Eigen::MatrixXd a;
    marginal.fill_basis(poles.data(), a);
    const MatrixL al = a.cast<long double>();
    const Eigen::JacobiSVD<MatrixL> svd(al, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const VectorL x = svd.solve(b);
    const double s_ref = static_cast<double>((b - al * x).squaredNorm());
    const double log_det_ref = static_cast<double>(2.0L * svd.singularValues().array().log().sum());
    const double cond = static_cast<double>(svd.singularValues()[0] / svd.singularValues()[a.cols() - 1]);
    const ResidueConditional& c = marginal.untruncated(poles.data());
    INFO("delta ", delta, ", cond(A) ", cond);
    if (!c.valid) {
      CHECK(cond > 1e9);
      continue;
    }
    const double log_det = 2.0 * (c.chol.diagonal().array().log().sum() - c.scale.array().log().sum());
    INFO("S_min ", c.s_min, " against ", s_ref, "; ln det M ", log_det, " against ", log_det_ref);
    CHECK(0.5 * c.nu * std::abs(std::log(c.s_min / s_ref)) <= kSminLogTolerance);
    CHECK(std::abs(log_det - log_det_ref) <= 0.01);
    const double y1 = c.mean.cwiseQuotient(c.scale).lpNorm<1>();
    if (y1 > kNormalEquationsGrowth * std::sqrt(static_cast<double>(b.squaredNorm()))) ++accepted_cancelling;
  }
  CHECK(accepted_cancelling >= 2);  // the QR path was exercised and accepted
}

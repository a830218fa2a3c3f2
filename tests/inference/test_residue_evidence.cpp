// SPDX-License-Identifier: MIT
// The closed-form marginal of the pole sampler (inference/residue_evidence.hpp; docs/method.md, "The
// closed-form marginal") against brute-force quadrature that shares none of its code: the model's own
// residue basis (model/residue_basis.hpp), the Gaussian prior density written out, and
//  - for Q0S0, a 2-D tensor Gauss-Legendre rule over G∞ and t = ln σ² of the Gaussian likelihood itself;
//  - for Q1S0 and Q0S1 at fixed poles, a tensor rule over the residues in the principal axes of their
//    least-squares covariance, with σ integrated by its own closed form (inference/likelihood.hpp,
//    ½ Γ(K/2) (π S)^{−K/2}).
// Cases: many data per residue (Gauss-Hermite path), few (ν = K − p < 40: adaptive Gauss-Kronrod path), and a
// prior that pulls the residues (admittance scale 0.2 with A = 5000 ≈ 3 prior standard deviations of s·λ; for Q0S0 0.02). The issue of accuracy is the σ quadrature
// (error < 0.01 nats asked); the brute-force rules are converged to 1e-5 nats (two rule sizes agree, checked
// below), so the tolerance is 1e-3 nats, ten times below what is asked and far above both rules' errors.
#include "core/rng.hpp"
#include "inference/evidence.hpp"
#include "inference/likelihood.hpp"
#include "inference/priors.hpp"
#include "inference/residue_evidence.hpp"
#include "model/residue_basis.hpp"
#include "synthetic_data.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

/// Composite Gauss-Legendre rule on [a, b]: `panels` panels of 16 nodes (Golub-Welsch).
void rule(double a, double b, int panels, std::vector<double>& x, std::vector<double>& w) {
  constexpr int m = 16;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m, m);
  for (int k = 1; k < m; ++k) j(k, k - 1) = j(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(j);
  x.clear();
  w.clear();
  const double h = (b - a) / panels;
  for (int p = 0; p < panels; ++p)
    for (int k = 0; k < m; ++k) {
      x.push_back(a + h * (p + 0.5 * (es.eigenvalues()[k] + 1.0)));
      w.push_back(h * es.eigenvectors()(0, k) * es.eigenvectors()(0, k));
    }
}

double log_normal_density(double x, double sd) { return -0.5 * std::log(2.0 * EIGEN_PI) - std::log(sd) - 0.5 * x * x / (sd * sd); }

/// ln ∫∫ N(G∞; 0, s²) (2πσ²)^{−K/2} e^{−S(G∞)/2σ²} dG∞ dσ/σ for Q0S0, by a 2-D tensor rule (dσ/σ = dt/2).
double q0s0_brute_force(const Measurement& data, double s, int panels) {
  const int k = real_data_count(DataCount::two_per_point, data.size());
  const double mean = data.y.real().mean();
  const double s_min = (data.y.real() - mean).square().sum() + data.y.imag().square().sum();
  const double sd = std::sqrt(s_min / k / static_cast<double>(data.size()));
  const double t_hat = std::log(s_min / k);
  std::vector<double> gx, gw, tx, tw;
  rule(mean - 40.0 * sd, mean + 40.0 * sd, panels, gx, gw);
  rule(t_hat - 12.0, t_hat + 30.0, panels, tx, tw);
  double acc = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < gx.size(); ++i) {
    const double ss = (data.y.real() - gx[i]).square().sum() + data.y.imag().square().sum();
    for (std::size_t j = 0; j < tx.size(); ++j) {
      const double log_f = log_normal_density(gx[i], s) - 0.5 * k * (std::log(2.0 * EIGEN_PI) + tx[j]) -
                           0.5 * ss * std::exp(-tx[j]) - std::log(2.0);
      acc = log_add_exp(acc, std::log(gw[i] * tw[j]) + log_f);
    }
  }
  return acc;
}

/// ln ∫ N(r; 0, D²) L(r) dr at fixed poles θ (residues ignored), L the σ-marginal likelihood, by a tensor rule
/// over r = r̂ + C z, z ∈ [−width, width]^p (C the Cholesky factor of the least-squares covariance
/// S_min/(K − p)·(AᵀA)⁻¹). `mean` receives the posterior mean of r.
double residues_brute_force(const Measurement& data, const Order& order, const Eigen::VectorXd& theta, double s,
                            double width, int panels, Eigen::VectorXd* mean = nullptr) {
  const ResidueBasis basis = residue_basis(order, theta, data.omega());
  const Eigen::Index n = data.size(), p = basis.re.cols();
  Eigen::MatrixXd a(2 * n, p);
  a << basis.re, basis.im;
  Eigen::VectorXd b(2 * n);
  b << data.y.real().matrix(), data.y.imag().matrix();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  const Eigen::VectorXd r_hat = qr.solve(b);
  const int k = real_data_count(DataCount::two_per_point, n);
  const double s_min = (b - a * r_hat).squaredNorm();
  const Eigen::MatrixXd cov = (a.transpose() * a).inverse() * (s_min / (k - static_cast<double>(p)));
  const Eigen::MatrixXd c = cov.llt().matrixL();
  const double log_jacobian = c.diagonal().array().log().sum();
  // Prior standard deviations written out (docs/method.md): s for G∞, s·λ for A, s·α for B and C.
  Eigen::VectorXd sd(p);
  sd[0] = s;
  for (int q = 0; q < order.q(); ++q) sd[1 + q] = s * theta[Order::lambda(q)];
  for (int j = 0; j < order.s(); ++j) sd[1 + order.q() + 2 * j] = sd[2 + order.q() + 2 * j] = s * theta[order.alpha(j)];
  const MarginalGaussian marginal(k);
  std::vector<double> x, w;
  rule(-width, width, panels, x, w);
  const auto nodes = static_cast<int>(x.size());
  std::vector<int> idx(static_cast<std::size_t>(p), 0);
  Eigen::VectorXd z(p);
  double acc = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd weighted = Eigen::VectorXd::Zero(p);
  std::vector<double> log_terms;
  std::vector<Eigen::VectorXd> points;
  for (;;) {
    double log_w = log_jacobian;
    for (Eigen::Index d = 0; d < p; ++d) {
      z[d] = x[static_cast<std::size_t>(idx[static_cast<std::size_t>(d)])];
      log_w += std::log(w[static_cast<std::size_t>(idx[static_cast<std::size_t>(d)])]);
    }
    const Eigen::VectorXd r = r_hat + c * z;
    double log_prior = 0.0;
    for (Eigen::Index d = 0; d < p; ++d) log_prior += log_normal_density(r[d], sd[d]);
    const double term = log_w + log_prior + marginal((b - a * r).squaredNorm());
    acc = log_add_exp(acc, term);
    if (mean != nullptr) {
      log_terms.push_back(term);
      points.push_back(r);
    }
    Eigen::Index d = 0;
    while (d < p && ++idx[static_cast<std::size_t>(d)] == nodes) idx[static_cast<std::size_t>(d++)] = 0;
    if (d == p) break;
  }
  if (mean != nullptr) {
    for (std::size_t i = 0; i < points.size(); ++i) weighted += std::exp(log_terms[i] - acc) * points[i];
    *mean = weighted;
  }
  return acc;
}

/// ψ of θ in inference/pole_space.hpp packing.
std::vector<double> poles_of(const Order& order, const Eigen::VectorXd& theta) {
  std::vector<double> psi;
  for (int q = 0; q < order.q(); ++q) psi.push_back(theta[Order::lambda(q)]);
  for (int j = 0; j < order.s(); ++j) {
    psi.push_back(theta[order.alpha(j)]);
    psi.push_back(theta[order.beta(j)]);
  }
  return psi;
}

}  // namespace

TEST_CASE("closed-form marginal: Q0S0 equals 2-D quadrature over G_inf and ln sigma^2 (both noise rules)") {
  const Order order(0, 0);
  Eigen::VectorXd truth(1);
  truth << 0.4;
  // 60 points: K = 120, ν = 119 (Gauss-Hermite); 5 points: K = 10, ν = 9 (Gauss-Kronrod). Seeds 3 and 4.
  for (const auto& [points, seed] : {std::pair{60, 3}, std::pair{5, 4}}) {
    const Measurement data = test::synthetic(order, truth, points, 100.0, 4000.0, 0.05, static_cast<std::uint64_t>(seed));
    for (const double s : {1.0, 0.02}) {
      const double ref = q0s0_brute_force(data, s, 40);
      REQUIRE(std::abs(ref - q0s0_brute_force(data, s, 30)) < 1e-5);
      const ResidueEvidence evidence(data, order, DataCount::two_per_point, s);
      const double closed = evidence(nullptr);
      INFO(points, " points, scale ", s, ": closed form ", closed, ", quadrature ", ref);
      CHECK(std::abs(closed - ref) < 1e-3);
    }
  }
}

TEST_CASE("closed-form marginal: Q1S0 and Q0S1 at fixed poles equal quadrature over the residues") {
  struct Case {
    Order order;
    Eigen::VectorXd truth;
    int points;
    double scale;
  };
  Eigen::VectorXd q1(3), s1(5);
  q1 << 0.3, 5000.0, 8000.0;                 // G∞, A, λ
  s1 << 0.5, 900.0, -200.0, 1500.0, 10000.0;  // G∞, B, C, α, β
  const std::vector<Case> cases{{Order(1, 0), q1, 30, 1.0},  {Order(1, 0), q1, 30, 0.2}, {Order(0, 1), s1, 24, 1.0},
                                {Order(0, 1), s1, 6, 1.0},   {Order(1, 0), q1, 5, 1.0}};
  for (const Case& c : cases) {
    const Measurement data = test::synthetic(c.order, c.truth, c.points, 100.0, 4000.0, 0.03, 21);
    // Few data (ν < 40): the t tails of the residues need a wider box.
    const double width = c.points < 10 ? 40.0 : 14.0;
    const int panels = c.order.q() == 1 ? 16 : (c.points < 10 ? 10 : 6);
    Eigen::VectorXd mean;
    const double ref = residues_brute_force(data, c.order, c.truth, c.scale, width, panels, &mean);
    REQUIRE(std::abs(ref - residues_brute_force(data, c.order, c.truth, c.scale, width, panels - 2)) < 1e-5);
    const ResidueEvidence evidence(data, c.order, DataCount::two_per_point, c.scale);
    const std::vector<double> psi = poles_of(c.order, c.truth);
    const ResiduePosterior& post = evidence.posterior(psi.data());
    INFO(c.order.name(), ", ", c.points, " points, scale ", c.scale, ": closed form ", post.log_evidence, ", quadrature ", ref);
    REQUIRE(post.valid);
    CHECK(std::abs(post.log_evidence - ref) < 1e-3);

    // Exact draws of (σ, r): their mean against the quadrature's posterior mean, within 4 Monte Carlo
    // standard errors per residue (sd/√n from the draws themselves; 4000 draws, seed 9).
    Rng rng(9);
    constexpr int kDraws = 4000;
    Eigen::MatrixXd draws(mean.size(), kDraws);
    for (int i = 0; i < kDraws; ++i) draws.col(i) = draw_residues(post, rng);
    const Eigen::VectorXd draw_mean = draws.rowwise().mean();
    for (Eigen::Index k = 0; k < mean.size(); ++k) {
      const double sd = std::sqrt((draws.row(k).array() - draw_mean[k]).square().sum() / (kDraws - 1));
      INFO("residue ", k, ": draws ", draw_mean[k], " ± ", sd / std::sqrt(double(kDraws)), ", quadrature ", mean[k]);
      CHECK(std::abs(draw_mean[k] - mean[k]) <= 4.0 * sd / std::sqrt(double(kDraws)));
    }
  }
}

TEST_CASE("closed-form marginal: the prior's limit and the least-squares residues") {
  // As the admittance scale shrinks the data cannot move G∞ away from 0, and L tends to the Gaussian
  // likelihood of r = 0: ½ Γ(K/2) (π |b|²)^{−K/2} (inference/likelihood.hpp), to O(s²·N/σ²) (here 1e-9 nats).
  const Order order(0, 0);
  Eigen::VectorXd truth(1);
  truth << 0.4;
  const Measurement data = test::synthetic(order, truth, 40, 100.0, 4000.0, 0.05, 5);
  const ResidueEvidence tiny(data, order, DataCount::two_per_point, 1e-9);
  const MarginalGaussian marginal(real_data_count(DataCount::two_per_point, data.size()));
  CHECK(std::abs(tiny(nullptr) - marginal(data.y.abs2().sum())) < 1e-6);
  // least_squares_residues: G∞ = mean of Re y (the least-squares fit of a constant), to rounding.
  const ResidueEvidence wide(data, order, DataCount::two_per_point, 1.0);
  CHECK(least_squares_residues(wide.posterior(nullptr))[0] == doctest::Approx(data.y.real().mean()).epsilon(1e-12));
}

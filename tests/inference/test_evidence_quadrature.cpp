// SPDX-License-Identifier: MIT
// Evidence against quadrature: nested-sampling ln Z against an independent deterministic
// quadrature of ∫ L π dθ, for Q0S0 (1-D) and Q1S0 (3-D) with priors narrowed so the tensor
// Gauss-Legendre rule is cheap and converged.
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/priors.hpp"
#include "inference/quadrature_evidence.hpp"
#include "synthetic_data.hpp"

#include <Eigen/Eigenvalues>
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

/// Gauss-Legendre nodes and weights on [−1, 1] by Golub-Welsch: the nodes are the eigenvalues of the
/// Jacobi matrix with off-diagonal k/√(4k² − 1); the weights are 2 v_0² (first eigenvector entries).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) j(k, k - 1) = j(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(j);
  x.assign(es.eigenvalues().data(), es.eigenvalues().data() + n);
  w.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) w[static_cast<std::size_t>(k)] = 2.0 * es.eigenvectors()(0, k) * es.eigenvectors()(0, k);
}

/// Composite rule on [−1, 1]: `panels` equal panels with an m-point Gauss-Legendre rule each.
void composite_rule(int panels, int m, std::vector<double>& x, std::vector<double>& w) {
  std::vector<double> gx, gw;
  gauss_legendre(m, gx, gw);
  x.clear();
  w.clear();
  const double h = 2.0 / panels;
  for (int p = 0; p < panels; ++p)
    for (int k = 0; k < m; ++k) {
      x.push_back(-1.0 + h * (p + 0.5 * (gx[static_cast<std::size_t>(k)] + 1.0)));
      w.push_back(0.5 * h * gw[static_cast<std::size_t>(k)]);
    }
}

/// ln of the prior-averaged likelihood (1/V) ∫ L dθ over the box, by a tensor composite rule with
/// `panels` × 16 nodes per dimension, accumulated in log space.
double log_z_quadrature(const Likelihood& like, const std::vector<Range>& box, int panels) {
  std::vector<double> x, w;
  composite_rule(panels, 16, x, w);
  const int n = static_cast<int>(x.size());
  const int dim = static_cast<int>(box.size());
  std::vector<int> idx(static_cast<std::size_t>(dim), 0);
  std::vector<double> theta(static_cast<std::size_t>(dim));
  double log_sum = -std::numeric_limits<double>::infinity();
  for (;;) {
    double log_w = 0.0;
    for (int d = 0; d < dim; ++d) {
      const auto k = static_cast<std::size_t>(idx[static_cast<std::size_t>(d)]);
      const Range& r = box[static_cast<std::size_t>(d)];
      theta[static_cast<std::size_t>(d)] = r.lo + 0.5 * r.width() * (x[k] + 1.0);
      log_w += std::log(0.5 * w[k]);  // ∫ over [lo,hi] dθ / (hi − lo) = ½ Σ w_k f(θ_k)
    }
    const double term = log_w + like(theta.data());
    const double m = std::max(log_sum, term);
    log_sum = m + std::log(std::exp(log_sum - m) + std::exp(term - m));
    int d = 0;
    while (d < dim && ++idx[static_cast<std::size_t>(d)] == n) idx[static_cast<std::size_t>(d++)] = 0;
    if (d == dim) break;
  }
  return log_sum;
}

NestedRun sample(const Likelihood& like, const PriorTransform& t, int live, std::uint64_t seed) {
  NestedSettings s;
  s.live = live;
  s.seed = seed;
  const Model model{t.order().parameter_names(), [&](const double* u, double* th) { t(u, th); },
                    [&](const double* th) { return like(th); }, [&](double* u) { t.fold(u); }};
  return run_nested_sampling(model, s);
}

}  // namespace

TEST_CASE("evidence: Q0S0 and Q1S0 agree with Gauss-Legendre quadrature within 3x the reported error") {
  // Data: Q1S0 truth (G∞ = 0.3, A = 5000 s⁻¹, λ = 8000 s⁻¹), 24 points 100-4000 Hz, σ = 0.05, seed 11.
  const Order truth_order(1, 0);
  Eigen::VectorXd truth(3);
  truth << 0.3, 5000.0, 8000.0;
  const Measurement data = test::synthetic(truth_order, truth, 24, 100.0, 4000.0, 0.05, 11);

  PriorRanges narrow;
  narrow.g_inf = {0.15, 0.45};
  narrow.a = {2000.0, 9000.0};
  narrow.lambda = {3000.0, 16000.0};

  struct Case {
    Order order;
    std::vector<Range> box;
  };
  const std::vector<Case> cases{{Order(0, 0), {Range{-1.0, 1.0}}},
                                {Order(1, 0), {narrow.g_inf, narrow.a, narrow.lambda}}};
  for (const Case& c : cases) {
    PriorRanges pr = narrow;
    if (c.order.q() == 0) pr.g_inf = {-1.0, 1.0};
    const Likelihood like(data, c.order, DataCount::two_per_point);
    // Convergence of the reference: two rule sizes agree to 1e-3 nats (far below the NS error ~0.1).
    const int n_fine = c.order.dim() == 1 ? 200 : 5, n_coarse = c.order.dim() == 1 ? 150 : 4;  // panels
    const double ref = log_z_quadrature(like, c.box, n_fine);
    REQUIRE(std::abs(ref - log_z_quadrature(like, c.box, n_coarse)) < 1e-3);

    const NestedRun run = sample(like, PriorTransform(c.order, pr, true), 400, 5);
    INFO(c.order.name(), ": quadrature ", ref, ", nested ", run.log_z, " ± ", run.log_z_error);
    CHECK(run.log_z_error > 0.0);
    CHECK(std::abs(run.log_z - ref) <= 3.0 * run.log_z_error);

    if (c.order.dim() == 1) {
      // The adaptive Gauss-Kronrod evidence (inference/quadrature_evidence.hpp) on the same 1-D model: its
      // target is 1e-6 relative in Z, so 2e-6 nats with the reference's own error.
      const PriorTransform t(c.order, pr, true);
      const Model model{c.order.parameter_names(), [&](const double* u, double* th) { t(u, th); },
                        [&](const double* th) { return like(th); }};
      const NestedRun q = evidence_by_quadrature(model);
      MESSAGE(c.order.name(), ": Gauss-Kronrod ", q.log_z, " ± ", q.log_z_error, " in ", q.calls, " calls");
      CHECK(std::abs(q.log_z - ref) <= 2e-6);
    }
  }
}

// SPDX-License-Identifier: MIT
// Lawson–Hanson LSI/NNLS (numerics/least_squares_inequality.hpp) against brute force: the optimum of a
// strictly convex QP is the equality-constrained least-squares solution of its active set, so the best
// feasible solution over all active sets (2^m of them, m ≤ 8) is an independent reference.
#include "core/rng.hpp"
#include "numerics/least_squares_inequality.hpp"
#include "test_support.hpp"

#include <Eigen/LU>
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace admitgen;
using test::random_matrix;
using numerics::least_squares_inequality;
using numerics::non_negative_least_squares;

namespace {

/// A random LSI problem with p unknowns, m constraints and p + 4 rows; h = G x0 − 0.2 for a random x0,
/// so x0 is feasible and the unconstrained optimum usually is not (active constraints at the optimum).
struct Problem {
  Eigen::MatrixXd e, g;
  Eigen::VectorXd f, h;
};
Problem random_problem(Rng& rng, Eigen::Index p, Eigen::Index m) {
  Problem q;
  q.e = random_matrix(rng, p + 4, p);
  q.g = random_matrix(rng, m, p);
  q.f = random_matrix(rng, p + 4, 1);
  const Eigen::VectorXd x0 = random_matrix(rng, p, 1);
  q.h = q.g * x0 - 0.2 * Eigen::VectorXd::Ones(m);
  return q;
}

/// min ‖E x − f‖² s.t. G x ≥ h by enumerating active sets (KKT system of each equality problem).
Eigen::VectorXd brute_force(const Eigen::MatrixXd& e, const Eigen::VectorXd& f, const Eigen::MatrixXd& g,
                            const Eigen::VectorXd& h, int& active_at_optimum) {
  const Eigen::Index p = e.cols(), m = g.rows();
  double best = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_x;
  for (unsigned mask = 0; mask < (1u << m); ++mask) {
    std::vector<Eigen::Index> act;
    for (Eigen::Index i = 0; i < m; ++i)
      if (mask & (1u << i)) act.push_back(i);
    if (static_cast<Eigen::Index>(act.size()) > p) continue;
    const Eigen::Index k = static_cast<Eigen::Index>(act.size());
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(p + k, p + k);
    Eigen::VectorXd rhs(p + k);
    kkt.topLeftCorner(p, p) = e.transpose() * e;
    rhs.head(p) = e.transpose() * f;
    for (Eigen::Index a = 0; a < k; ++a) {
      kkt.block(p + a, 0, 1, p) = g.row(act[static_cast<std::size_t>(a)]);
      kkt.block(0, p + a, p, 1) = g.row(act[static_cast<std::size_t>(a)]).transpose();
      rhs[p + a] = h[act[static_cast<std::size_t>(a)]];
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
    if (!lu.isInvertible()) continue;
    const Eigen::VectorXd x = lu.solve(rhs).head(p);
    if (((g * x - h).array() < -1e-10).any()) continue;
    const double obj = (e * x - f).squaredNorm();
    if (obj < best) best = obj, best_x = x, active_at_optimum = static_cast<int>(k);
  }
  return best_x;
}

}  // namespace

TEST_CASE("LSI: Lawson-Hanson equals brute-force active-set enumeration on 40 random problems") {
  Rng rng(1974);
  int with_active = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto [e, g, f, h] = random_problem(rng, 2 + trial % 4, 3 + trial % 6);
    int active = 0;
    const Eigen::VectorXd ref = brute_force(e, f, g, h, active);
    const auto sol = least_squares_inequality(e, f, g, h);
    REQUIRE(sol.feasible);
    // Both solve p×p systems with condition numbers ≲ 1e3 here: agreement to 1e-9 leaves a wide margin
    // over ε·cond and cannot pass for a wrong active set (which moves x by O(0.1)).
    CAPTURE(trial);
    CHECK((sol.x - ref).norm() <= 1e-9 * (1.0 + ref.norm()));
    CHECK(((g * sol.x - h).array() >= -1e-12).all());
    with_active += active > 0;
  }
  CHECK(with_active >= 20);  // the catalogue exercises active constraints, not only interior optima
}

TEST_CASE("LSI: inconsistent constraints are reported infeasible") {
  Eigen::MatrixXd e = Eigen::MatrixXd::Identity(2, 2), g(2, 2);
  g << 1, 0, -1, 0;  // x0 ≥ 1 and −x0 ≥ 0
  Eigen::VectorXd f(2), h(2);
  f << 0, 0;
  h << 1, 0;
  CHECK_FALSE(least_squares_inequality(e, f, g, h).feasible);
}

TEST_CASE("NNLS: equals brute-force enumeration of zero sets on 30 random problems") {
  Rng rng(1995);
  for (int trial = 0; trial < 30; ++trial) {
    const Eigen::Index n = 2 + trial % 5, rows = n + 2 + trial % 3;
    const Eigen::MatrixXd a = random_matrix(rng, rows, n);
    const Eigen::VectorXd b = random_matrix(rng, rows, 1);
    int active = 0;
    const Eigen::VectorXd ref = brute_force(a, b, Eigen::MatrixXd::Identity(n, n), Eigen::VectorXd::Zero(n), active);
    const Eigen::VectorXd x = non_negative_least_squares(a, b);
    CAPTURE(trial);
    CHECK((x - ref).norm() <= 1e-9 * (1.0 + ref.norm()));
    CHECK((x.array() >= 0.0).all());
  }
}

TEST_CASE("LSI: degenerate constraint sets (each row repeated, with rounding-level copies) give the same optimum") {
  // Dense frequency grids give many nearly parallel constraints: the degenerate case where a textbook NNLS
  // can cycle. Each row appears three times (exactly, and scaled by 1 ± 1e-15); the optimum is unchanged.
  Rng rng(23);
  for (int trial = 0; trial < 20; ++trial) {
    const auto [e, g, f, h] = random_problem(rng, 3 + trial % 3, 4 + trial % 4);
    const Eigen::Index p = e.cols(), m = g.rows();
    int active = 0;
    const Eigen::VectorXd ref = brute_force(e, f, g, h, active);
    Eigen::MatrixXd g3(3 * m, p);
    Eigen::VectorXd h3(3 * m);
    g3 << g, g * (1.0 + 1e-15), g * (1.0 - 1e-15);
    h3 << h, h * (1.0 + 1e-15), h * (1.0 - 1e-15);
    const auto sol = least_squares_inequality(e, f, g3, h3);
    REQUIRE(sol.feasible);
    CAPTURE(trial);
    CHECK((sol.x - ref).norm() <= 1e-8 * (1.0 + ref.norm()));
  }
}

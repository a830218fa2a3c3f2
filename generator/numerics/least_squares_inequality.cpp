// SPDX-License-Identifier: MIT
#include "numerics/least_squares_inequality.hpp"

#include "core/errors.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace admitgen::numerics {
namespace {

/// Least squares on the columns in `set` only (others 0), by column-pivoted QR.
Eigen::VectorXd solve_on(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const std::vector<bool>& set) {
  std::vector<Eigen::Index> cols;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    if (set[static_cast<std::size_t>(j)]) cols.push_back(j);
  Eigen::MatrixXd sub(a.rows(), static_cast<Eigen::Index>(cols.size()));
  for (std::size_t k = 0; k < cols.size(); ++k) sub.col(static_cast<Eigen::Index>(k)) = a.col(cols[k]);
  const Eigen::VectorXd zs = sub.colPivHouseholderQr().solve(b);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(a.cols());
  for (std::size_t k = 0; k < cols.size(); ++k) z[cols[k]] = zs[static_cast<Eigen::Index>(k)];
  return z;
}

}  // namespace

Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.cols();
  ADMITGEN_ENSURE(a.rows() == b.size(), "NNLS: {} rows but {} right-hand sides", a.rows(), b.size());
  // Tolerance on the dual (gradient) test: rounding in Aᵀ(b − Ax) is ~ ε ‖A‖ ‖b‖ per entry.
  const double tol = 10.0 * std::numeric_limits<double>::epsilon() * std::max<double>(a.rows(), n) *
                     a.cwiseAbs().maxCoeff() * std::max(b.cwiseAbs().maxCoeff(), 1e-300);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(static_cast<std::size_t>(n), false);  // the set P of Lawson–Hanson
  // Each outer step adds one index; each inner step removes at least one: 3n outer steps bound the work
  // in practice (L&H prove finite termination; the cap only guards against cycling by rounding).
  // An index whose least-squares coefficient comes out ≤ 0 right after it entered P can only do so by
  // rounding (its gradient w_t > 0 says it should grow); re-adding it would cycle forever, so it is
  // skipped until x next changes (the safeguard of Lawson & Hanson §23.3, step 6, and of later codes).
  std::vector<bool> skipped(static_cast<std::size_t>(n), false);
  for (int outer = 0; outer < 3 * static_cast<int>(n) + 10; ++outer) {
    const Eigen::VectorXd w = a.transpose() * (b - a * x);
    Eigen::Index t = -1;
    double best = tol;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[static_cast<std::size_t>(j)] && !skipped[static_cast<std::size_t>(j)] && w[j] > best) best = w[j], t = j;
    if (t < 0) break;  // Kuhn–Tucker conditions hold (up to the skipped, rounding-level indices)
    passive[static_cast<std::size_t>(t)] = true;
    if (solve_on(a, b, passive)[t] <= 0.0) {
      passive[static_cast<std::size_t>(t)] = false;
      skipped[static_cast<std::size_t>(t)] = true;
      continue;
    }
    std::fill(skipped.begin(), skipped.end(), false);
    for (int inner = 0; inner < static_cast<int>(n) + 1; ++inner) {
      const Eigen::VectorXd z = solve_on(a, b, passive);
      double alpha = 1.0;
      Eigen::Index limiting = -1;  // the index that stops the step: it leaves P, so every inner step shrinks P
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[static_cast<std::size_t>(j)] && z[j] <= 0.0) {
          const double step = x[j] / (x[j] - z[j]);
          if (limiting < 0 || step < alpha) alpha = step, limiting = j;
        }
      if (limiting < 0) {
        x = z;
        break;
      }
      x += alpha * (z - x);
      x[limiting] = 0.0;
      // Coefficients driven to (rounding-level) zero by the step leave P too.
      const double floor = 1e-14 * std::max(1.0, x.cwiseAbs().maxCoeff());
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[static_cast<std::size_t>(j)] && x[j] <= floor) passive[static_cast<std::size_t>(j)] = false, x[j] = 0.0;
    }
  }
  return x;
}

LsiSolution least_squares_inequality(const Eigen::MatrixXd& e, const Eigen::VectorXd& f, const Eigen::MatrixXd& g,
                                     const Eigen::VectorXd& h) {
  const Eigen::Index p = e.cols();
  ADMITGEN_ENSURE(e.rows() == f.size() && g.cols() == p && g.rows() == h.size(), "LSI: inconsistent sizes");
  // Equilibrate: x = D y with D = 1/‖column‖ (the basis columns of slow and fast poles differ by
  // decades); every constraint row scaled to unit norm (the solution is unchanged).
  const Eigen::VectorXd d = e.colwise().norm().transpose().cwiseMax(1e-300).cwiseInverse();
  const Eigen::MatrixXd es = e * d.asDiagonal();
  Eigen::MatrixXd gs = g * d.asDiagonal();
  Eigen::VectorXd hs = h;
  for (Eigen::Index i = 0; i < gs.rows(); ++i) {
    const double n = gs.row(i).norm();
    if (n > 0.0) gs.row(i) /= n, hs[i] /= n;
  }
  // E = Q R: ‖E y − f‖² = ‖R y − Q₁ᵀ f‖² + const. With z = R y − Q₁ᵀ f the problem is the LDP
  // min ‖z‖ s.t. (G R⁻¹) z ≥ h − G R⁻¹ Q₁ᵀ f   (L&H eq. 23.5-23.8).
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(es);
  const Eigen::MatrixXd r = qr.matrixQR().topRows(p).triangularView<Eigen::Upper>();
  const Eigen::VectorXd f1 = (qr.householderQ().transpose() * f).head(p);
  const Eigen::MatrixXd a = r.triangularView<Eigen::Upper>().transpose().solve(gs.transpose()).transpose();  // G R⁻¹
  const Eigen::VectorXd rhs = hs - a * f1;
  LsiSolution out;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(p);
  if (a.rows() > 0 && (rhs.array() > 0.0).any()) {
    // LDP by NNLS (L&H §23.3): u ≥ 0 minimising ‖[Aᵀ; rhsᵀ] u − e_{p+1}‖; if the residual r ≠ 0,
    // z = −r_{1..p} / r_{p+1}; r = 0 means the constraints are inconsistent.
    Eigen::MatrixXd big(p + 1, a.rows());
    big.topRows(p) = a.transpose();
    big.row(p) = rhs.transpose();
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(p + 1);
    unit[p] = 1.0;
    const Eigen::VectorXd u = non_negative_least_squares(big, unit);
    const Eigen::VectorXd res = big * u - unit;
    if (!(std::abs(res[p]) > 1e-12)) return out;  // infeasible
    z = -res.head(p) / res[p];
  }
  out.feasible = true;
  out.x = d.asDiagonal() * r.triangularView<Eigen::Upper>().solve(z + f1);
  return out;
}

}  // namespace admitgen::numerics

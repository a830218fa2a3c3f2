// SPDX-License-Identifier: MIT
#include "passivity/pole_refit.hpp"

#include "model/residue_basis.hpp"
#include "numerics/least_squares_inequality.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace admitgen::passivity {
namespace {

/// The margin fraction of the first constraint solve (passive_residues.cpp): the refit works at it.
constexpr double kMarginFraction = 1e-9;
/// Stop when an accepted step lowers F by less than this fraction of F (twice in a row): the last digits
/// of a fit whose noise is ≥ 1e-4 of the data.
constexpr double kRelativeTolerance = 1e-7;
/// Stop when the damping exceeds this multiple of D²: the step is then shorter than rounding.
constexpr double kMaxDamping = 1e12;
/// The largest step of a pole in one iteration: a rate by a factor of 10 (|δ ln x| ≤ ln 10), β by 10× the
/// pair's modulus |α + jβ|. Keeps every trial finite (an undamped first step can ask for e^50) while letting
/// a pole cross the band in a few steps.
constexpr double kMaxLogStep = 2.302585092994046;
constexpr double kMaxBetaStep = 10.0;
/// The box the search stays in (docs/passivity.md, "Searching the poles"), unless the start lies outside it:
/// λ ≥ ω_min/10 (a real pole further below the band acts there as A/jω, whatever λ, so the data cannot place
/// it, and a near-DC pole makes float filters stall: a limit cycle), α ≥ the smallest spacing of the data
/// frequencies (a resonance narrower than that is not resolved), rates ≤ 10 ω_max and |β| ≤ 10 ω_max.
constexpr double kLambdaFloor = 0.1;
constexpr double kCeiling = 10.0;

/// Pole sets whose equilibrated residue basis has a reciprocal condition number below this are refused: two
/// poles merging (an over-complete order) make the basis rank-deficient, the residues huge and cancelling,
/// and the constraint solve unreliable. 1e-10 keeps ~6 significant digits in the residues.
constexpr double kMinReciprocalCondition = 1e-10;

/// |R_pp| / |R_11| of the column-pivoted QR of E with unit-norm columns: an estimate of 1/cond(E).
double reciprocal_condition(const Eigen::MatrixXd& e) {
  const Eigen::VectorXd norms = e.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(e * norms.cwiseInverse().asDiagonal());
  const Eigen::VectorXd r = qr.matrixR().diagonal().cwiseAbs();
  return r.size() == 0 || r[0] == 0.0 ? 0.0 : r[r.size() - 1] / r[0];
}

/// Index into θ of pole coordinate k (ψ = λ_1..λ_Q, α_1, β_1, .., α_S, β_S).
int pole_index(const Order& order, int k) {
  if (k < order.q()) return Order::lambda(k);
  const int s = (k - order.q()) / 2;
  return (k - order.q()) % 2 == 0 ? order.alpha(s) : order.beta(s);
}

/// Whether coordinate k is a rate (λ or α: stepped in its logarithm, so it stays positive).
bool is_rate(const Order& order, int k) { return k < order.q() || (k - order.q()) % 2 == 0; }

/// ∂/∂u of the pole derivatives: ∂/∂ln x = x ∂/∂x for the rates.
void to_step_coordinates(const Order& order, const Eigen::VectorXd& theta, Eigen::MatrixXd& d) {
  for (int k = 0; k < order.buffers(); ++k)
    if (is_rate(order, k)) d.col(k) *= theta[pole_index(order, k)];
}

/// Everything the step needs at the current poles.
struct Linearisation {
  Eigen::MatrixXd j;       ///< 2N × (p + m): [A, ∂(A r)/∂u]
  Eigen::VectorXd eps;     ///< f − A r
  Eigen::MatrixXd c;       ///< (|Ω| + 2m) × (p + m): ∂ Re G(ω_j) / ∂(r, u), then the step bounds' rows
  Eigen::VectorXd re_g;    ///< Re G(ω_j)
  Eigen::VectorXd bounds;  ///< right-hand sides of the step bounds' rows (kMaxLogStep, kMaxBetaStep, PoleBox)
};

/// Lower and upper limits of each pole coordinate u (ln λ, ln α, β) for a search from `start`.
struct PoleBox {
  Eigen::VectorXd lo, hi;
};

PoleBox pole_box(const Order& order, const Eigen::VectorXd& start, const ResidueTarget& target) {
  const Eigen::ArrayXd& w = target.omega;
  double spacing = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 1; i < w.size(); ++i) spacing = std::min(spacing, std::abs(w[i] - w[i - 1]));
  const double w_min = w.size() > 0 ? w.minCoeff() : 0.0, ceiling = kCeiling * (w.size() > 0 ? w.maxCoeff() : 0.0);
  PoleBox b{Eigen::VectorXd(order.buffers()), Eigen::VectorXd(order.buffers())};
  for (int k = 0; k < order.buffers(); ++k) {
    const double x = start[pole_index(order, k)];
    if (!is_rate(order, k)) {
      b.lo[k] = -std::max(std::abs(x), ceiling), b.hi[k] = std::max(std::abs(x), ceiling);
      continue;
    }
    const double floor = k < order.q() ? kLambdaFloor * w_min : (std::isfinite(spacing) ? spacing : 0.0);
    b.lo[k] = std::log(std::min(x, floor)), b.hi[k] = std::log(std::max(x, ceiling));
  }
  return b;
}

/// u of θ (the coordinates of PoleBox).
double coordinate(const Order& order, const Eigen::VectorXd& theta, int k) {
  const double x = theta[pole_index(order, k)];
  return is_rate(order, k) ? std::log(x) : x;
}

Linearisation linearise(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target,
                        const PoleBox& box) {
  const int p = residue_count(order), m = order.buffers();
  Eigen::MatrixXd e;
  Eigen::VectorXd f;
  weighted_system(order, theta, target, e, f);
  const Eigen::Index n = target.omega.size();
  Linearisation l;
  l.j = Eigen::MatrixXd::Zero(e.rows(), p + m);
  l.j.leftCols(p) = e;
  ResidueBasis d = pole_derivatives(order, theta, target.omega);
  to_step_coordinates(order, theta, d.re);
  to_step_coordinates(order, theta, d.im);
  l.j.block(0, p, n, m) = target.weights.matrix().asDiagonal() * d.re;
  l.j.block(n, p, n, m) = target.weights.matrix().asDiagonal() * d.im;
  const Eigen::VectorXd r = residues_of(order, theta);
  if (e.rows() > 2 * n) {
    // The prior's rows σ r_k / s_k: s_A,q ∝ λ_q and s_B,s = s_C,s ∝ α_s, so ∂/∂ ln λ_q (∂/∂ ln α_s) of the
    // row is minus the row (docs/passivity.md, "Under the residue prior").
    const Eigen::VectorXd rows = prior_row_weights(order, theta, target).cwiseProduct(r);
    for (int q = 0; q < order.q(); ++q) l.j(2 * n + 1 + q, p + q) = -rows[1 + q];
    for (int s = 0; s < order.s(); ++s)
      for (int k = 0; k < 2; ++k)
        l.j(2 * n + 1 + order.q() + 2 * s + k, p + order.q() + 2 * s) = -rows[1 + order.q() + 2 * s + k];
  }
  l.eps = f - e * r;
  const std::vector<double> grid = constraint_grid(order, theta, target);
  const Eigen::ArrayXd w = Eigen::Map<const Eigen::ArrayXd>(grid.data(), Eigen::Index(grid.size()));
  const Eigen::MatrixXd g = residue_basis(order, theta, w).re;
  Eigen::MatrixXd dg = pole_derivatives(order, theta, w).re;
  to_step_coordinates(order, theta, dg);
  l.c = Eigen::MatrixXd::Zero(g.rows() + 2 * m, p + m);
  l.c.topRows(g.rows()) << g, dg;
  l.re_g = g * r;
  l.bounds = Eigen::VectorXd::Zero(2 * m);
  for (int k = 0; k < m; ++k) {  // lo_k ≤ δu_k ≤ hi_k as the rows δu_k ≥ lo_k and −δu_k ≥ −hi_k
    const int s = (k - order.q()) / 2;
    const double step = is_rate(order, k) ? kMaxLogStep
                                          : kMaxBetaStep * std::hypot(theta[order.alpha(s)], theta[order.beta(s)]);
    const double u = coordinate(order, theta, k);
    l.c(g.rows() + 2 * k, p + k) = 1.0;
    l.c(g.rows() + 2 * k + 1, p + k) = -1.0;
    l.bounds[2 * k] = std::max(-step, std::min(0.0, box.lo[k] - u));
    l.bounds[2 * k + 1] = -std::min(step, std::max(0.0, box.hi[k] - u));
  }
  return l;
}

/// θ with pole coordinates moved by δu (rates multiplied by e^δu).
Eigen::VectorXd moved(const Order& order, const Eigen::VectorXd& theta, const Eigen::VectorXd& du) {
  Eigen::VectorXd out = theta;
  for (int k = 0; k < order.buffers(); ++k) {
    const int i = pole_index(order, k);
    out[i] = is_rate(order, k) ? theta[i] * std::exp(du[k]) : theta[i] + du[k];
  }
  return out;
}

}  // namespace

ProjectedResidues project_residues(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target) {
  Eigen::MatrixXd e;
  Eigen::VectorXd f;
  weighted_system(order, theta, target, e, f);
  ProjectedResidues out;
  out.theta = theta;
  if (!e.allFinite() || reciprocal_condition(e) < kMinReciprocalCondition) return out;
  const std::vector<double> grid = constraint_grid(order, theta, target);
  const Eigen::ArrayXd w = Eigen::Map<const Eigen::ArrayXd>(grid.data(), Eigen::Index(grid.size()));
  const Eigen::MatrixXd g = residue_basis(order, theta, w).re;
  const double margin = constraint_margin(target, kMarginFraction);
  const auto sol = numerics::least_squares_inequality(e, f, g, Eigen::VectorXd::Constant(g.rows(), 2.0 * margin));
  if (!sol.feasible || !sol.x.allFinite()) return out;
  out.feasible = true;
  set_residues(order, sol.x, out.theta);
  out.sum_squares = (f - e * sol.x).squaredNorm();
  return out;
}

PoleRefit refit_poles(const Order& order, const Eigen::VectorXd& start, const ResidueTarget& target, int max_steps) {
  const ProjectedResidues first = project_residues(order, start, target);
  PoleRefit out;
  out.theta = first.theta;
  out.start_sum_squares = out.sum_squares = first.sum_squares;
  const int p = residue_count(order), m = order.buffers();
  if (m == 0 || !first.feasible) {  // an ill-conditioned start (nearly coincident poles) is not searched from
    if (!first.feasible) out.start_sum_squares = out.sum_squares = std::numeric_limits<double>::infinity();
    return out;
  }
  const double margin = constraint_margin(target, kMarginFraction);
  Eigen::VectorXd d2 = Eigen::VectorXd::Zero(p + m);
  double mu = -1.0, nu = 2.0;  // damping relative to D² (set at the first step), Nielsen's growth factor
  int small = 0;
  const PoleBox box = pole_box(order, start, target);
  Linearisation l = linearise(order, out.theta, target, box);
  for (out.steps = 0; out.steps < max_steps;) {
    ++out.steps;
    d2 = d2.cwiseMax(l.j.colwise().squaredNorm().transpose());
    const Eigen::VectorXd dd = d2.cwiseMax(1e-12 * d2.maxCoeff()).cwiseSqrt();  // a column of zeros stays damped
    if (mu < 0.0) mu = 1e-3;
    Eigen::MatrixXd e(l.j.rows() + p + m, p + m);
    e << l.j, Eigen::MatrixXd(std::sqrt(mu) * dd.asDiagonal());
    Eigen::VectorXd f = Eigen::VectorXd::Zero(e.rows());
    f.head(l.eps.size()) = l.eps;
    // At margin δ (the current point meets 2δ): δ = 0 is strictly feasible, so the LSI always has a solution.
    Eigen::VectorXd h(l.c.rows());
    h << (margin - l.re_g.array()).matrix(), l.bounds;
    const auto step = numerics::least_squares_inequality(e, f, l.c, h);
    if (!step.feasible || !step.x.allFinite()) break;
    const double predicted = l.eps.squaredNorm() - (l.eps - l.j * step.x).squaredNorm();
    const ProjectedResidues trial = project_residues(order, moved(order, out.theta, step.x.tail(m)), target);
    const double gain = out.sum_squares - trial.sum_squares;
    if (trial.feasible && gain > 0.0) {
      ++out.accepted;
      const double rho = predicted > 0.0 ? gain / predicted : 1.0;
      mu *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
      nu = 2.0;
      small = gain < kRelativeTolerance * out.sum_squares ? small + 1 : 0;
      out.theta = trial.theta;
      out.sum_squares = trial.sum_squares;
      if (small >= 2) break;
      l = linearise(order, out.theta, target, box);
    } else {
      mu *= nu;
      nu *= 2.0;
      if (mu > kMaxDamping) break;
    }
  }
  return out;
}

Eigen::VectorXd canonical_terms(const Order& order, const Eigen::VectorXd& theta) {
  Eigen::VectorXd out = theta;
  std::vector<int> q(static_cast<std::size_t>(order.q())), s(static_cast<std::size_t>(order.s()));
  std::iota(q.begin(), q.end(), 0);
  std::iota(s.begin(), s.end(), 0);
  std::stable_sort(q.begin(), q.end(), [&](int a, int b) { return theta[Order::lambda(a)] < theta[Order::lambda(b)]; });
  std::stable_sort(s.begin(), s.end(), [&](int a, int b) {
    return std::abs(theta[order.beta(a)]) < std::abs(theta[order.beta(b)]);
  });
  for (int k = 0; k < order.q(); ++k) {
    out[Order::a(k)] = theta[Order::a(q[k])];
    out[Order::lambda(k)] = theta[Order::lambda(q[k])];
  }
  for (int k = 0; k < order.s(); ++k) {
    const int from = s[static_cast<std::size_t>(k)];
    const double sign = theta[order.beta(from)] < 0.0 ? -1.0 : 1.0;
    out[order.b(k)] = theta[order.b(from)];
    out[order.c(k)] = sign * theta[order.c(from)];
    out[order.alpha(k)] = theta[order.alpha(from)];
    out[order.beta(k)] = sign * theta[order.beta(from)];
  }
  return out;
}

}  // namespace admitgen::passivity

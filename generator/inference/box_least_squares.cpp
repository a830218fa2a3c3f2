// SPDX-License-Identifier: MIT
#include "inference/box_least_squares.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <vector>

namespace admitgen {

Eigen::VectorXd box_least_squares(const Eigen::MatrixXd& m, const Eigen::VectorXd& c, const Eigen::VectorXd& lo,
                                  const Eigen::VectorXd& hi, bool* converged, int max_iterations) {
  const Eigen::Index p = c.size();
  if (max_iterations <= 0) max_iterations = static_cast<int>(8 * p + 20);
  enum State : signed char { at_lo = -1, free_ = 0, at_hi = 1 };
  std::vector<State> state(static_cast<std::size_t>(p), free_);
  Eigen::VectorXd x(p);
  for (Eigen::Index k = 0; k < p; ++k) {
    x[k] = std::clamp(c[k], lo[k], hi[k]);
    if (c[k] < lo[k]) state[static_cast<std::size_t>(k)] = at_lo;
    if (c[k] > hi[k]) state[static_cast<std::size_t>(k)] = at_hi;
  }
  if (converged) *converged = false;
  std::vector<Eigen::Index> fr;
  Eigen::MatrixXd m_ff;
  Eigen::VectorXd rhs, target;
  Eigen::LDLT<Eigen::MatrixXd> ldlt;
  const double scale = m.diagonal().cwiseAbs().maxCoeff();
  for (int it = 0; it < max_iterations; ++it) {
    fr.clear();
    for (Eigen::Index k = 0; k < p; ++k)
      if (state[static_cast<std::size_t>(k)] == free_) fr.push_back(k);
    const Eigen::Index f = static_cast<Eigen::Index>(fr.size());
    // Minimiser over the free coordinates with the bound ones fixed: M_FF (x_F − c_F) = −M_FB (x_B − c_B).
    target = x;
    if (f > 0) {
      m_ff.resize(f, f);
      rhs.resize(f);
      const Eigen::VectorXd d = x - c;
      for (Eigen::Index i = 0; i < f; ++i) {
        double s = 0.0;
        for (Eigen::Index k = 0; k < p; ++k)
          if (state[static_cast<std::size_t>(k)] != free_) s -= m(fr[static_cast<std::size_t>(i)], k) * d[k];
        rhs[i] = s;
        for (Eigen::Index j = 0; j < f; ++j) m_ff(i, j) = m(fr[static_cast<std::size_t>(i)], fr[static_cast<std::size_t>(j)]);
      }
      ldlt.compute(m_ff);
      if (ldlt.info() != Eigen::Success) return x;
      const Eigen::VectorXd y = ldlt.solve(rhs);
      for (Eigen::Index i = 0; i < f; ++i) target[fr[static_cast<std::size_t>(i)]] = c[fr[static_cast<std::size_t>(i)]] + y[i];
    }
    // Walk from x towards the target; the first coordinate to meet a bound stops the step.
    double t = 1.0;
    Eigen::Index blocking = -1;
    for (Eigen::Index i = 0; i < f; ++i) {
      const Eigen::Index k = fr[static_cast<std::size_t>(i)];
      const double step = target[k] - x[k];
      if (target[k] > hi[k] && step > 0.0 && (hi[k] - x[k]) / step < t) {
        t = (hi[k] - x[k]) / step;
        blocking = k;
      } else if (target[k] < lo[k] && step < 0.0 && (lo[k] - x[k]) / step < t) {
        t = (lo[k] - x[k]) / step;
        blocking = k;
      }
    }
    t = std::max(t, 0.0);
    for (Eigen::Index i = 0; i < f; ++i) {
      const Eigen::Index k = fr[static_cast<std::size_t>(i)];
      x[k] = std::clamp(x[k] + t * (target[k] - x[k]), lo[k], hi[k]);
    }
    if (blocking >= 0) {
      x[blocking] = target[blocking] > hi[blocking] ? hi[blocking] : lo[blocking];
      state[static_cast<std::size_t>(blocking)] = target[blocking] > hi[blocking] ? at_hi : at_lo;
      continue;
    }
    // Stationary on the free set: the gradient 2M(x − c) must point out of the box at every bound
    // coordinate (≥ 0 at a lower bound, ≤ 0 at an upper one); free the worst offender.
    const Eigen::VectorXd grad = m * (x - c);
    Eigen::Index worst = -1;
    double worst_value = 1e-12 * scale * std::max(1.0, (x - c).cwiseAbs().maxCoeff());
    for (Eigen::Index k = 0; k < p; ++k) {
      const State s = state[static_cast<std::size_t>(k)];
      const double wrong = s == at_lo ? -grad[k] : s == at_hi ? grad[k] : 0.0;
      if (wrong > worst_value) {
        worst_value = wrong;
        worst = k;
      }
    }
    if (worst < 0) {
      if (converged) *converged = true;
      return x;
    }
    state[static_cast<std::size_t>(worst)] = free_;
  }
  return x;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "checks/state_space.hpp"

#include "core/errors.hpp"

#include <Eigen/LU>

#include <cmath>

namespace admitgen::checks {

StateSpace continuous_realisation(const Order& order, const double* theta) {
  const Eigen::Index n = order.buffers();
  StateSpace ss{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n), Eigen::RowVectorXd::Zero(n),
                theta[Order::g_inf()]};
  Eigen::Index i = 0;
  for (int q = 0; q < order.q(); ++q, ++i) {
    ss.A(i, i) = -theta[Order::lambda(q)];
    ss.B[i] = 1.0;
    ss.C[i] = theta[Order::a(q)];
  }
  for (int s = 0; s < order.s(); ++s, i += 2) {
    const double alpha = theta[order.alpha(s)], beta = theta[order.beta(s)];
    ss.A.block<2, 2>(i, i) << -alpha, beta, -beta, -alpha;
    ss.B[i] = 1.0;
    ss.C[i] = 2.0 * theta[order.b(s)];
    ss.C[i + 1] = -2.0 * theta[order.c(s)];
  }
  return ss;
}

StateSpace discrete_realisation(const codegen::DiscreteModel& m) {
  const Eigen::Index taps = static_cast<Eigen::Index>(m.fir.size());
  const Eigen::Index delay = taps > 1 ? taps - 1 : 0;
  const Eigen::Index n = static_cast<Eigen::Index>(m.real.size() + 2 * m.pair.size()) + delay;
  StateSpace ss{Eigen::MatrixXd::Zero(n, n), Eigen::VectorXd::Zero(n), Eigen::RowVectorXd::Zero(n),
                taps > 0 ? m.fir[0] : 0.0};
  Eigen::Index i = 0;
  for (const auto& r : m.real) {
    const double a = 1.0 - r.eps;
    ss.A(i, i) = a;
    ss.B[i] = r.eps;
    ss.C[i] = r.c * a;
    ss.D += r.c * r.eps;
    ++i;
  }
  for (const auto& p : m.pair) {
    // ψ = ξ + jη; π ψ = [(1+e_r)ξ − p_i η] + j[p_i ξ + (1+e_r) η]; output 2 Re(c ψ) = 2c_r ξ − 2c_i η.
    Eigen::Matrix2d pi;
    pi << 1.0 + p.e_r, -p.p_i, p.p_i, 1.0 + p.e_r;
    const Eigen::RowVector2d out(2.0 * p.c.real(), -2.0 * p.c.imag());
    ss.A.block<2, 2>(i, i) = pi;
    ss.B[i] = p.g;
    ss.C.segment<2>(i) = out * pi;
    ss.D += out[0] * p.g;
    i += 2;
  }
  // Delay line: state k holds u^{n−1−k}; y += d_{k+1} · state k.
  for (Eigen::Index k = 0; k < delay; ++k) {
    if (k == 0)
      ss.B[i] = 1.0;
    else
      ss.A(i + k, i + k - 1) = 1.0;
    ss.C[i + k] = m.fir[static_cast<std::size_t>(k + 1)];
  }
  return ss;
}

StateSpace bilinear_to_continuous(const StateSpace& d) {
  const Eigen::Index n = d.states();
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(d.A + I);
  ADMITGEN_ENSURE(n == 0 || std::abs(lu.determinant()) > 0.0, "discrete realisation has a pole at z = -1");
  StateSpace c;
  c.A = lu.solve(d.A - I);
  c.B = std::sqrt(2.0) * lu.solve(d.B);
  // C (A + I)^{-1} = ((A + I)^{-T} Cᵀ)ᵀ
  const Eigen::RowVectorXd c_inv = (d.A + I).transpose().partialPivLu().solve(d.C.transpose()).transpose();
  c.C = std::sqrt(2.0) * c_inv;
  c.D = d.D - c_inv.dot(d.B);
  return c;
}

}  // namespace admitgen::checks

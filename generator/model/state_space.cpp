// SPDX-License-Identifier: MIT
#include "model/state_space.hpp"

#include "core/errors.hpp"

#include <Eigen/LU>

#include <cmath>

namespace admitgen {

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

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Paper eq. 2 written term by term with std::complex: the independent reference the model's vectorised
/// evaluation and its residue basis are tested against.
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>

#include <complex>

namespace admitgen::test {

inline std::complex<double> eq2_reference(const Order& o, const Eigen::VectorXd& th, double w) {
  const std::complex<double> jw(0.0, w);
  std::complex<double> g = th[0];
  for (int q = 0; q < o.q(); ++q) g += th[Order::a(q)] / (th[Order::lambda(q)] + jw);
  for (int s = 0; s < o.s(); ++s) {
    const std::complex<double> big(th[o.b(s)], th[o.c(s)]), pole(th[o.alpha(s)], th[o.beta(s)]);
    g += big / (pole + jw) + std::conj(big) / (std::conj(pole) + jw);
  }
  return g;
}

}  // namespace admitgen::test

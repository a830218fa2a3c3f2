// SPDX-License-Identifier: MIT
#include "model/residue_basis.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <complex>

namespace admitgen {

int residue_count(const Order& order) { return 1 + order.q() + 2 * order.s(); }

std::vector<int> residue_indices(const Order& order) {
  std::vector<int> idx{Order::g_inf()};
  for (int q = 0; q < order.q(); ++q) idx.push_back(Order::a(q));
  for (int s = 0; s < order.s(); ++s) {
    idx.push_back(order.b(s));
    idx.push_back(order.c(s));
  }
  return idx;
}

Eigen::VectorXd residues_of(const Order& order, const Eigen::VectorXd& theta) {
  const auto idx = residue_indices(order);
  Eigen::VectorXd r(static_cast<Eigen::Index>(idx.size()));
  for (std::size_t k = 0; k < idx.size(); ++k) r[static_cast<Eigen::Index>(k)] = theta[idx[k]];
  return r;
}

void set_residues(const Order& order, const Eigen::VectorXd& r, Eigen::VectorXd& theta) {
  const auto idx = residue_indices(order);
  ADMITGEN_ENSURE(r.size() == static_cast<Eigen::Index>(idx.size()), "{} has {} residues, got {}", order.name(),
                  idx.size(), r.size());
  for (std::size_t k = 0; k < idx.size(); ++k) theta[idx[k]] = r[static_cast<Eigen::Index>(k)];
}

ResidueBasis residue_basis(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega) {
  ADMITGEN_ENSURE(theta.size() == order.dim(), "{} needs {} parameters, got {}", order.name(), order.dim(),
                  theta.size());
  using cplx = std::complex<double>;
  const Eigen::Index n = omega.size(), p = residue_count(order);
  ResidueBasis b{Eigen::MatrixXd::Zero(n, p), Eigen::MatrixXd::Zero(n, p)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = omega[i];
    b.re(i, 0) = 1.0;
    if (std::isinf(w)) continue;  // every pole term vanishes at infinite frequency
    Eigen::Index k = 1;
    for (int q = 0; q < order.q(); ++q, ++k) {
      const cplx phi = 1.0 / cplx(theta[Order::lambda(q)], w);
      b.re(i, k) = phi.real();
      b.im(i, k) = phi.imag();
    }
    for (int s = 0; s < order.s(); ++s, k += 2) {
      const double al = theta[order.alpha(s)], be = theta[order.beta(s)];
      const cplx plus = 1.0 / cplx(al, w + be), minus = 1.0 / cplx(al, w - be);
      const cplx phi_b = plus + minus, phi_c = cplx(0.0, 1.0) * (plus - minus);
      b.re(i, k) = phi_b.real();
      b.im(i, k) = phi_b.imag();
      b.re(i, k + 1) = phi_c.real();
      b.im(i, k + 1) = phi_c.imag();
    }
  }
  return b;
}

ResidueBasis pole_derivatives(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega) {
  ADMITGEN_ENSURE(theta.size() == order.dim(), "{} needs {} parameters, got {}", order.name(), order.dim(),
                  theta.size());
  using cplx = std::complex<double>;
  const cplx j(0.0, 1.0);
  const Eigen::Index n = omega.size(), m = order.buffers();
  ResidueBasis d{Eigen::MatrixXd::Zero(n, m), Eigen::MatrixXd::Zero(n, m)};
  const auto put = [&](Eigen::Index i, Eigen::Index k, cplx v) { d.re(i, k) = v.real(), d.im(i, k) = v.imag(); };
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = omega[i];
    if (std::isinf(w)) continue;  // every pole term and its derivatives vanish at infinite frequency
    Eigen::Index k = 0;
    for (int q = 0; q < order.q(); ++q, ++k) {
      const cplx phi = 1.0 / cplx(theta[Order::lambda(q)], w);
      put(i, k, -theta[Order::a(q)] * phi * phi);
    }
    for (int s = 0; s < order.s(); ++s, k += 2) {
      const double al = theta[order.alpha(s)], be = theta[order.beta(s)];
      const cplx res(theta[order.b(s)], theta[order.c(s)]);
      const cplx plus = 1.0 / cplx(al, w + be), minus = 1.0 / cplx(al, w - be);
      const cplx p2 = res * plus * plus, m2 = std::conj(res) * minus * minus;
      put(i, k, -p2 - m2);
      put(i, k + 1, -j * p2 + j * m2);
    }
  }
  return d;
}

}  // namespace admitgen

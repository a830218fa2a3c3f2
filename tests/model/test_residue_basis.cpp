// SPDX-License-Identifier: MIT
// The residue basis (model/residue_basis.hpp) against paper eq. 2 written term by term.
#include "core/rng.hpp"
#include "model/eq2_reference.hpp"
#include "model/residue_basis.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <limits>

using namespace admitgen;

TEST_CASE("residue basis: basis times residues is eq. 2 for random orders and parameters") {
  Rng rng(20261123);
  for (const Order o : {Order(0, 0), Order(1, 0), Order(0, 2), Order(2, 1), Order(3, 3)}) {
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd th(o.dim());
      th[0] = rng.uniform() - 0.5;
      for (int q = 0; q < o.q(); ++q) th[Order::a(q)] = 8e4 * (rng.uniform() - 0.5), th[Order::lambda(q)] = 100.0 + 7e4 * rng.uniform();
      for (int s = 0; s < o.s(); ++s) {
        th[o.b(s)] = 2e4 * (rng.uniform() - 0.5), th[o.c(s)] = 2e3 * (rng.uniform() - 0.5);
        th[o.alpha(s)] = 10.0 + 2e4 * rng.uniform(), th[o.beta(s)] = 3e4 * (rng.uniform() - 0.5);
      }
      Eigen::ArrayXd w(5);
      w << 0.0, 2 * M_PI * 100.0, 2 * M_PI * 1000.0, 2 * M_PI * 4000.0, std::numeric_limits<double>::infinity();
      const ResidueBasis b = residue_basis(o, th, w);
      const Eigen::VectorXd r = residues_of(o, th);
      REQUIRE(r.size() == residue_count(o));
      for (Eigen::Index i = 0; i < w.size(); ++i) {
        const std::complex<double> g = std::isinf(w[i]) ? std::complex<double>(th[0], 0.0) : test::eq2_reference(o, th, w[i]);
        // Each of ≤ 1 + Q + 2S terms is exact to a few ulp of its own size; the sum is bounded by Σ|r_k φ_k|.
        double scale = 0.0;
        for (Eigen::Index k = 0; k < r.size(); ++k) scale += std::abs(r[k]) * std::hypot(b.re(i, k), b.im(i, k));
        CHECK(std::abs(b.re.row(i).dot(r) - g.real()) <= 1e-14 * scale);
        CHECK(std::abs(b.im.row(i).dot(r) - g.imag()) <= 1e-14 * scale);
      }
      Eigen::VectorXd th2 = Eigen::VectorXd::Zero(o.dim());
      th2 = th;
      set_residues(o, Eigen::VectorXd::Zero(r.size()), th2);
      CHECK(residues_of(o, th2).norm() == 0.0);
      set_residues(o, r, th2);
      CHECK((th2 - th).norm() == 0.0);
    }
  }
}

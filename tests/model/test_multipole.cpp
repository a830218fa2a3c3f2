// SPDX-License-Identifier: MIT
// The vectorised multipole evaluation against two independent forms of the same model.
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "model/eq2_reference.hpp"
#include "model/multipole.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

using namespace admitgen;

namespace {

/// docs/physics.md §1.1: one pair as a real second-order section (2Bs + 2(Bα + Cβ))/(s² + 2αs + α² + β²).
std::complex<double> pair_as_sos(double b, double c, double al, double be, double w) {
  const std::complex<double> s(0.0, w);
  return (2.0 * b * s + 2.0 * (b * al + c * be)) / (s * s + 2.0 * al * s + al * al + be * be);
}

Eigen::VectorXd random_theta(const Order& o, Rng& rng) {
  Eigen::VectorXd th(o.dim());
  th[0] = rng.uniform() - 0.5;
  for (int q = 0; q < o.q(); ++q) {
    th[Order::a(q)] = 8e4 * (rng.uniform() - 0.5);
    th[Order::lambda(q)] = 100.0 + 7e4 * rng.uniform();
  }
  for (int s = 0; s < o.s(); ++s) {
    th[o.b(s)] = 2e4 * (rng.uniform() - 0.5);
    th[o.c(s)] = 2e3 * (rng.uniform() - 0.5);
    th[o.alpha(s)] = 10.0 + 2e4 * rng.uniform();
    th[o.beta(s)] = 3e4 * (rng.uniform() - 0.5);
  }
  return th;
}

}  // namespace

TEST_CASE("multipole: every order of Q0-3 x S0-3 matches the term-by-term complex form") {
  // Each term is a handful of flops on values of similar magnitude; relative error is a few ulp per
  // term, so 1e-12 relative to the largest term magnitude (|A|/λ, |Θ|/α) is generous yet decisive.
  Rng rng(42);
  Eigen::ArrayXd omega = Eigen::ArrayXd::LinSpaced(300, std::log(2 * EIGEN_PI * 50), std::log(2 * EIGEN_PI * 8000)).exp();
  for (const Order& o : order_grid(3, 3)) {
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::VectorXd th = random_theta(o, rng);
      const Eigen::ArrayXcd g = evaluate_multipole(o, th, omega);
      double scale = 1.0;
      for (int q = 0; q < o.q(); ++q) scale += std::abs(th[Order::a(q)]) / th[Order::lambda(q)];
      for (int s = 0; s < o.s(); ++s) scale += std::hypot(th[o.b(s)], th[o.c(s)]) / th[o.alpha(s)];
      for (Eigen::Index i = 0; i < omega.size(); ++i) REQUIRE(std::abs(g[i] - test::eq2_reference(o, th, omega[i])) <= 1e-12 * scale);
    }
  }
}

TEST_CASE("multipole: a pair equals its real second-order section - beta sign flip with C is a symmetry") {
  const Order o(0, 1);
  Eigen::VectorXd th(5);
  th << 0.0, 2019.0, -263.0, 1530.0, 10063.0;
  Eigen::VectorXd flipped = th;
  flipped[o.c(0)] = -th[o.c(0)];
  flipped[o.beta(0)] = -th[o.beta(0)];
  const Eigen::ArrayXd omega = Eigen::ArrayXd::LinSpaced(50, 500.0, 30000.0);
  const Eigen::ArrayXcd g = evaluate_multipole(o, th, omega), gf = evaluate_multipole(o, flipped, omega);
  for (Eigen::Index i = 0; i < omega.size(); ++i) {
    const auto sos = pair_as_sos(2019.0, -263.0, 1530.0, 10063.0, omega[i]);
    CHECK(std::abs(g[i] - sos) <= 1e-13 * std::abs(sos) + 1e-15);
    CHECK(std::abs(g[i] - gf[i]) <= 1e-15 * (1.0 + std::abs(g[i])));
  }
}

TEST_CASE("order: names, packing and parsing") {
  const Order o = Order::parse("q1s2");
  CHECK(o.name() == "Q1S2");
  CHECK(o.dim() == 11);
  CHECK(o.buffers() == 5);
  const auto names = o.parameter_names();
  REQUIRE(names.size() == 11);
  CHECK(names[Order::lambda(0)] == "lambda_1");
  CHECK(names[o.b(1)] == "B_2");
  CHECK(names[o.beta(1)] == "beta_2");
  CHECK_THROWS_AS(Order::parse("Q-1S1"), InputError);
  CHECK_THROWS_AS(Order::parse("Q1"), InputError);
  CHECK_THROWS_AS(Order(0, 17), InputError);
  CHECK(order_grid(1, 2).size() == 6);
}

// SPDX-License-Identifier: MIT
// The normal equations of the pole sampler (inference/residue_gram.hpp), computed from per-pole sums by
// partial fractions, against M = ReΦᵀReΦ + ImΦᵀImΦ and g = ReΦᵀRe D + ImΦᵀIm D formed directly from the
// model's basis matrices (model/residue_basis.hpp) by Eigen products: no code in common but the data.
//
// Tolerance. Both sides sum N ≤ 1000 terms in double precision: each entry carries a rounding error below
// N·ε ≈ 2.2e-13 of the sum of the magnitudes of its terms, which is ≤ √(M_uu M_vv) (Cauchy-Schwarz). The
// partial fractions add one error: (conj T_a + T_b) loses digits when T_a ≈ T_b, the loss growing with
// |Im T|/Re T ≈ (distance of the pole from the nearest point)/(its damping). The cases below keep that
// ratio ≤ 1e3 (a pair as sharp as α = Δω/1000 on a grid point, poles a decade outside the band), so errors
// stay below about 1e3 · 2.2e-13 ≈ 2e-10 of √(M_uu M_vv); the tolerance is 1e-9 of it. g is compared on
// the scale √(M_uu)·|D|, its Cauchy-Schwarz bound.
#include "core/rng.hpp"
#include "data/measurement.hpp"
#include "inference/residue_gram.hpp"
#include "model/order.hpp"
#include "model/residue_basis.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace admitgen;

namespace {

struct Reference {
  Eigen::MatrixXd m;
  Eigen::VectorXd g;
};

Reference direct(const Order& order, const std::vector<double>& poles, const Eigen::ArrayXd& omega,
                 const Eigen::ArrayXcd& data) {
  // θ packed as model/order.hpp; the poles in the packing of inference/pole_space.hpp (λ_q, then α_s, β_s).
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(order.dim());
  for (int q = 0; q < order.q(); ++q) theta[Order::lambda(q)] = poles[static_cast<std::size_t>(q)];
  for (int s = 0; s < order.s(); ++s) {
    theta[order.alpha(s)] = poles[static_cast<std::size_t>(order.q() + 2 * s)];
    theta[order.beta(s)] = poles[static_cast<std::size_t>(order.q() + 2 * s + 1)];
  }
  const ResidueBasis basis = residue_basis(order, theta, omega);
  return {basis.re.transpose() * basis.re + basis.im.transpose() * basis.im,
          basis.re.transpose() * data.real().matrix() + basis.im.transpose() * data.imag().matrix()};
}

void compare(const Order& order, const std::vector<double>& poles, const Eigen::ArrayXd& omega,
             const Eigen::ArrayXcd& data) {
  const Reference ref = direct(order, poles, omega, data);
  const int p = residue_count(order);
  const GramPoints points(omega, data);
  std::vector<double> m(static_cast<std::size_t>(p * p)), g(static_cast<std::size_t>(p));
  residue_gram(points, order.q(), order.s(), poles.data(), m.data(), g.data());
  const double data_norm = std::sqrt(data.abs2().sum());
  for (int u = 0; u < p; ++u) {
    for (int v = 0; v < p; ++v) {
      const double scale = std::sqrt(ref.m(u, u) * ref.m(v, v));
      INFO(order.name(), " M(", u, ",", v, ") = ", m[static_cast<std::size_t>(u + v * p)], " against ", ref.m(u, v));
      CHECK(std::abs(m[static_cast<std::size_t>(u + v * p)] - ref.m(u, v)) <= 1e-9 * scale);
    }
    INFO(order.name(), " g(", u, ") = ", g[static_cast<std::size_t>(u)], " against ", ref.g[u]);
    CHECK(std::abs(g[static_cast<std::size_t>(u)] - ref.g[u]) <= 1e-9 * std::sqrt(ref.m(u, u)) * data_norm);
  }
}

}  // namespace

TEST_CASE("residue_gram: normal equations by partial fractions equal the direct products") {
  // 997 points (not a multiple of the 8 lanes: the padding is exercised), 100 Hz to 4 kHz.
  const int n = 997;
  Eigen::ArrayXd omega(n);
  for (int i = 0; i < n; ++i) omega[i] = 2.0 * EIGEN_PI * (100.0 + 3900.0 * i / (n - 1));
  const double w_max = omega[n - 1], dw = omega[1] - omega[0];
  Rng rng(20261127);
  Eigen::ArrayXcd data(n);
  for (int i = 0; i < n; ++i) data[i] = {0.3 + 0.1 * rng.normal(), -0.2 + 0.1 * rng.normal()};

  SUBCASE("poles drawn from the band prior's ranges") {
    for (int trial = 0; trial < 20; ++trial) {
      const Order order(trial % 4, 1 + trial % 3);
      std::vector<double> poles;
      for (int q = 0; q < order.q(); ++q) poles.push_back(4.0 * w_max * rng.uniform());
      for (int s = 0; s < order.s(); ++s) {
        poles.push_back(4.0 * w_max * rng.uniform());
        poles.push_back(2.0 * w_max * (2.0 * rng.uniform() - 1.0));
      }
      compare(order, poles, omega, data);
    }
  }
  SUBCASE("hard cases: sharp pairs on a point, near-equal poles, poles far below and above the band") {
    const double on_point = omega[400];
    compare(Order(0, 2), {dw / 1000.0, on_point, dw / 900.0, on_point + dw / 1000.0}, omega, data);
    compare(Order(2, 0), {omega[0] / 10.0, omega[0] / 10.0 * (1.0 + 1e-9)}, omega, data);
    compare(Order(2, 2), {10.0 * w_max, 10.0 * w_max * (1.0 + 1e-6), 10.0 * w_max, -9.0 * w_max, 1.0, 3.0 * w_max},
            omega, data);
    compare(Order(1, 1), {omega[0] / 10.0, omega[0] / 10.0, 0.0}, omega, data);
  }
}

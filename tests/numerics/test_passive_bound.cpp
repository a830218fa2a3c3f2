// SPDX-License-Identifier: MIT
// The passive bound (numerics/passive_bound.hpp, docs/passivity.md "The passive bound"). References, each
// independent of the code under test: a closed form (no passive G comes nearer a negative constant than G = 0),
// exact data of a certified passive model (the bound must fall to the hats' interpolation error), and the
// Hilbert integral of a hat by quadrature where it is regular.
#include "model/multipole.hpp"
#include "model/order.hpp"
#include "model/passivity.hpp"
#include "numerics/passive_bound.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>

using namespace admitgen;

namespace {

constexpr double kTwoPi = 6.283185307179586;

numerics::PassiveBound bound_on_band(const Eigen::ArrayXcd& values, const Eigen::ArrayXd& omega) {
  return numerics::passive_bound(omega, values, Eigen::ArrayXd::Ones(omega.size()));
}

/// 400 points, linear in f from 200 to 2000 Hz, as a tube export spaces them.
Eigen::ArrayXd tube_band() { return kTwoPi * Eigen::ArrayXd::LinSpaced(400, 200.0, 2000.0); }

/// A passive Q1S2 (certified below): G∞ 0.1, a relaxation and two damped resonances, one inside the band.
Eigen::VectorXd passive_truth() {
  Eigen::VectorXd th(1 + 2 + 4 * 2);
  th << 0.1, 800.0, 1500.0,           // G∞; A, λ
      300.0, 100.0, 400.0, 6000.0,    // B, C, α, β: 955 Hz, Q ≈ 7.5
      900.0, -200.0, 3000.0, 20000.0; // above the band
  return th;
}

}  // namespace

TEST_CASE("passive bound: no passive admittance comes nearer a negative constant than G = 0 (residual exactly 100 %)") {
  // Re G ≥ 0 gives |−c − G| ≥ Re G + c ≥ c at every point, and G = 0 attains it: the relative residual is 1.
  // Every term offered has Re ≥ 0, so the dual test of NNLS stops at x = 0; a term with Re < 0 anywhere in the
  // band (a wrong sign in the hats) would lower it. Tolerance: rounding of two norms of 800 entries.
  const Eigen::ArrayXd w = tube_band();
  const auto b = bound_on_band(Eigen::ArrayXcd::Constant(w.size(), {-0.3, 0.0}), w);
  CHECK(b.relative_rms_residual == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(b.terms == 0);
}

TEST_CASE("passive bound: exact data of a certified passive model are followed to the hats' interpolation error") {
  const Order order(1, 2);
  const Eigen::VectorXd th = passive_truth();
  REQUIRE(continuous_passivity(order, th.data()).passive);
  const Eigen::ArrayXd w = tube_band();
  const auto b = bound_on_band(evaluate_multipole(order, th, w), w);
  // The hats interpolate u = Re G linearly between nodes 1.8 % apart (128 per decade): the error in u is about
  // h²/8 |u''| with h = 0.018 ω; at the in-band resonance (Q ≈ 7.5, half width 6.7 % of ω) u'' ~ u / 0.067² ω²,
  // so about 1 % of the peak there, less elsewhere; its Hilbert transform carries the same size into Im G.
  // Measured 0.25 % of the data's norm; 1 % leaves a margin of 4. A wrong sign or scale in the hats' imaginary
  // part (the Hilbert integral) leaves tens of per cent, as the anti-causal case below shows.
  CHECK(b.relative_rms_residual < 1e-2);
  CHECK(b.terms > 0);
}

TEST_CASE("passive bound: data passive in band but anti-causal are far from every passive wall") {
  // conj G(jω) has the same Re part ≥ 0 as the passive truth, so every point looks passive, but its imaginary part
  // has the sign of a response that precedes its cause: the Kramers-Kronig relations fail and no passive G follows.
  const Order order(1, 2);
  const Eigen::ArrayXd w = tube_band();
  const Eigen::ArrayXcd y = evaluate_multipole(order, passive_truth(), w);
  const auto causal = bound_on_band(y, w);
  const auto anti = bound_on_band(y.conjugate(), w);
  // Measured 59.7 % against 0.25 %.
  CHECK(anti.relative_rms_residual > 0.2);
  CHECK(anti.relative_rms_residual > 50.0 * causal.relative_rms_residual);
}

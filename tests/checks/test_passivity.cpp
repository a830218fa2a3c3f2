// SPDX-License-Identifier: MIT
// Exact (Hamiltonian) passivity test against dense frequency scans (checks/passivity.hpp).
#include "checks/passivity.hpp"
#include "core/rng.hpp"
#include "model/multipole.hpp"
#include "model/passivity.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace admitgen;
using namespace admitgen::checks;

namespace {

constexpr double kPi = 3.14159265358979323846;

double re_g(const Order& o, const Eigen::VectorXd& th, double f_hz) {
  Eigen::ArrayXd re, im;
  evaluate_multipole(o, th.data(), Eigen::ArrayXd::Constant(1, 2 * kPi * f_hz), re, im);
  return re[0];
}

/// Sign changes of Re G on a log grid of n points over [lo, hi] Hz (the midpoint of each changing cell).
std::vector<double> scan_crossings(const Order& o, const Eigen::VectorXd& th, double lo, double hi, int n) {
  std::vector<double> out;
  double prev_f = lo, prev = re_g(o, th, lo);
  for (int i = 1; i < n; ++i) {
    const double f = lo * std::pow(hi / lo, double(i) / (n - 1)), v = re_g(o, th, f);
    if ((v < 0.0) != (prev < 0.0)) out.push_back(std::sqrt(f * prev_f));
    prev = v, prev_f = f;
  }
  return out;
}

/// The band edges inside the scan's range 1 Hz - 1 MHz, in order (what scan_crossings sees).
std::vector<double> band_edges(const PassivityResult& p) {
  std::vector<double> edges;
  for (const auto& b : p.bands) {
    if (b.lo > 1.0) edges.push_back(b.lo);
    if (std::isfinite(b.hi) && b.hi < 1e6) edges.push_back(b.hi);
  }
  return edges;
}

/// A random model: Q, S in 0..2, poles 50 Hz - 20 kHz, residues of both signs (about half non-passive).
Eigen::VectorXd random_model(Rng& rng, Order& order) {
  order = Order(static_cast<int>(rng.below(3)), 1 + static_cast<int>(rng.below(2)));
  Eigen::VectorXd th(order.dim());
  const auto rate = [&] { return 2 * kPi * 50.0 * std::pow(400.0, rng.uniform()); };
  th[Order::g_inf()] = 0.05 * rng.uniform();
  for (int q = 0; q < order.q(); ++q) {
    th[Order::lambda(q)] = rate();
    th[Order::a(q)] = th[Order::lambda(q)] * 0.5 * (rng.uniform() - 0.5);
  }
  for (int s = 0; s < order.s(); ++s) {
    th[order.beta(s)] = rate();
    th[order.alpha(s)] = th[order.beta(s)] * (0.02 + 0.5 * rng.uniform());
    th[order.b(s)] = th[order.alpha(s)] * 0.4 * (rng.uniform() - 0.6);
    th[order.c(s)] = th[order.alpha(s)] * 0.4 * (rng.uniform() - 0.5);
  }
  return th;
}

}  // namespace

TEST_CASE("Hamiltonian crossings agree with a dense scan on random models") {
  // Dense scan: 200 000 log points over 1 Hz - 1 MHz, cell ratio 1e6^(1/199999) - 1 = 6.9e-5. A scan sign
  // change must have a Hamiltonian crossing within one cell (relative 7e-5) and vice versa, except bands
  // narrower than a cell (none at these dampings: alpha >= 0.02 beta). The polished crossings are roots of
  // Re G to |Re G| <= 1e-9 of the model scale.
  Rng rng(20240611);
  int non_passive = 0, compared = 0;
  for (int trial = 0; trial < 16; ++trial) {
    Order order(0, 0);
    const Eigen::VectorXd th = random_model(rng, order);
    const PassivityResult p = continuous_passivity(order, th.data());
    const auto scan = scan_crossings(order, th, 1.0, 1e6, 200000);
    const std::vector<double> edges = band_edges(p);
    CAPTURE(trial);
    CAPTURE(order.name());
    REQUIRE(edges.size() == scan.size());
    for (std::size_t i = 0; i < scan.size(); ++i) {
      CHECK(std::abs(edges[i] - scan[i]) <= 7e-5 * scan[i]);
      CHECK(std::abs(re_g(order, th, edges[i])) <= 1e-9 * (1.0 + std::abs(th[0])));
      ++compared;
    }
    non_passive += p.passive ? 0 : 1;
    CHECK(p.passive == (scan.empty() && re_g(order, th, 1.0) >= 0.0 && th[0] >= 0.0));
  }
  CHECK(non_passive >= 3);  // the sample exercises both outcomes
  CHECK(compared >= 6);
}

TEST_CASE("Hamiltonian crossings of a nearly defective model (real pole and pair at the same rate) equal a scan") {
  // A posterior sample of a Q1S1 fit: lambda = 19 714 s^-1 and a pair alpha = 19 748 s^-1 with beta = 0.98 s^-1,
  // so A has three nearly equal eigenvalues and the real Schur iteration of the 6 x 6 Hamiltonian does not
  // converge; the complex Schur iteration must. Reference: the dense scan of the first test case (cell ratio
  // 6.9e-5); Re G here has no narrow band (every rate is ~3 kHz), so edges and scan agree cell for cell.
  const Order order(1, 1);
  Eigen::VectorXd th(order.dim());
  th[Order::g_inf()] = 0.872017;
  th[Order::a(0)] = 39774.4756537347;
  th[Order::lambda(0)] = 19713.9232041093;
  th[order.b(0)] = -605.434901484852 / 2.0;
  th[order.c(0)] = -1677.56575711787 / 2.0;
  th[order.alpha(0)] = 19748.0742229794;
  th[order.beta(0)] = 0.980658104084796;
  const PassivityResult p = continuous_passivity(order, th.data());
  const auto scan = scan_crossings(order, th, 1.0, 1e6, 200000);
  const std::vector<double> edges = band_edges(p);
  REQUIRE(edges.size() == scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) CHECK(std::abs(edges[i] - scan[i]) <= 7e-5 * scan[i]);
  CHECK(p.passive == (scan.empty() && re_g(order, th, 1.0) >= 0.0));
}

TEST_CASE("Hamiltonian test finds a 0.7 Hz wide non-passive band a 1000-point scan misses") {
  // G = 0.02 + pair at 2 kHz with Q = 2000 and peak Re = B/alpha = -0.03: Re G < 0 where
  // 0.03/(1 + x^2) > 0.02, x = (w - beta)/alpha, i.e. |x| < 0.707: width 1.41 alpha/2pi = 0.71 Hz.
  const Order order(0, 1);
  Eigen::VectorXd th(order.dim());
  const double alpha = 2 * kPi * 0.5;
  th << 0.02, -0.03 * alpha, 0.0, alpha, 2 * kPi * 2000.0;
  double coarse_min = 1e9;
  for (int i = 0; i < 1000; ++i) coarse_min = std::min(coarse_min, re_g(order, th, 10.0 * std::pow(2000.0, i / 999.0)));
  CHECK(coarse_min > 0.0);  // the scan (spacing 0.76 %, 15 Hz at 2 kHz) sees a passive model
  const PassivityResult p = continuous_passivity(order, th.data());
  REQUIRE(p.bands.size() == 1);
  CHECK(p.bands[0].hi - p.bands[0].lo == doctest::Approx(1.414 * 0.5).epsilon(0.02));
  CHECK(p.bands[0].min_re == doctest::Approx(0.02 - 0.03).epsilon(1e-3));
  CHECK(p.bands[0].at == doctest::Approx(2000.0).epsilon(1e-4));
  CHECK_FALSE(is_passive(order, th.data()));
}

TEST_CASE("a model whose residues cancel by six orders of magnitude is found non-passive where Re G < 0") {
  // A posterior sample of a Q4S4 fit of a real grey-foam tube file (400-2000 Hz), along a nearly degenerate residue
  // direction: residues up to 2.5e8 for |G| ~ 1e3. Rounding moved the Hamiltonian's imaginary-axis eigenvalues off
  // the axis, no crossing was found, and the model was certified passive. The reference is Re G evaluated directly
  // (re_g, a sum of eight terms of at most ~1e4 each: rounding ~1e-12) at 5358.88 Hz: -1225, and at 200 Hz: -0.40.
  const Order order(4, 4);
  Eigen::VectorXd th(order.dim());
  th << 1880.782732818646, 2459836.9263175502, 1216.5547138562667, -2512054.657162241, 1228.0792164311167,
      60183.230565830425, 1919.3017668699351, -246576337.11877432, 37132.30598622294, -3287.7448445249233,
      43360.31722129556, 449.5524976492636, 14666.330924794245, 349663.84493879037, 2710206.724945405,
      5128.077140018174, 17563.596569514135, 13773174.477885474, 124228338.12659416, 29710.548133197943,
      18590.294429890193, 4477857.533545113, -135.52183607538313, 1498.2227224155968, 20851.366774695314;
  REQUIRE(re_g(order, th, 5358.88) < -1000.0);
  REQUIRE(re_g(order, th, 200.0) < -0.3);
  const PassivityResult p = continuous_passivity(order, th.data());
  CHECK_FALSE(p.passive);
  CHECK(p.min_re < -1000.0);
  bool at_200_hz = false;  // the narrow low band is found too, not only the deep one
  for (const auto& b : p.bands) at_200_hz = at_200_hz || (b.lo < 200.0 && b.hi > 200.0);
  CHECK(at_200_hz);
  CHECK_FALSE(is_passive(order, th.data()));
}

TEST_CASE("passivity edge cases: G_inf = 0 (reciprocal realisation), G_inf < 0, term-wise conditions") {
  // One real pole, G_inf = 0: Re G = A lambda/(lambda^2 + w^2) > 0, tends to 0 at infinity: passive.
  const Order q1(1, 0);
  Eigen::VectorXd th(q1.dim());
  th << 0.0, 1000.0, 2000.0;
  auto p = continuous_passivity(q1, th.data());
  CHECK(p.passive);
  CHECK(p.method.find("reciprocal") != std::string::npos);
  // G_inf < 0 with a strong pole: negative above the crossing where A lambda/(lambda^2 + w^2) = 0.1,
  // w^2 = A lambda/0.1 - lambda^2 = 3.6e7 → f = 954.9 Hz, band to infinity.
  th << -0.1, 2000.0, 2000.0;
  p = continuous_passivity(q1, th.data());
  REQUIRE(p.bands.size() == 1);
  CHECK(p.bands[0].lo == doctest::Approx(std::sqrt(2000.0 * 2000.0 / 0.1 - 4e6) / (2 * kPi)).epsilon(1e-9));
  CHECK(std::isinf(p.bands[0].hi));
  CHECK_FALSE(is_passive(q1, th.data()));
  // docs/physics.md §2.2: a pair violating |C| beta <= B alpha can still be passive overall (decided exactly).
  const Order s1(0, 1);
  Eigen::VectorXd ts(s1.dim());
  ts << 0.5, 100.0, 120.0, 1000.0, 6000.0;  // |C| beta = 7.2e5 > B alpha = 1e5
  CHECK(std::abs(ts[2] * ts[4]) > ts[1] * ts[3]);
  CHECK(is_passive(s1, ts.data()) == continuous_passivity(s1, ts.data()).passive);
  CHECK(is_passive(s1, ts.data()));
}

// SPDX-License-Identifier: MIT
// Exact (Hamiltonian) passivity test against dense frequency scans (checks/passivity.hpp).
#include "checks/check_suite.hpp"
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

namespace {

/// Independent reference for the certificate (docs/passivity.md, "What the certificate guarantees"): Re G in
/// long double (64-bit mantissa), term by term from the partial fractions, on 400 000 log points over
/// 0.1 Hz - 1 MHz (cell ratio 5.8e-5) plus 40 001 linear points across ±40 alpha of every pair (spacing
/// alpha/500). The bands the certificate must find are ≥ 0.06 Hz wide (≥ 30 cells of the pair grids).
struct DenseMinimum {
  long double min_re = 0;
  double at_hz = 0;
};

long double re_g_long(const Order& o, const Eigen::VectorXd& th, long double w) {
  long double r = th[Order::g_inf()];
  for (int q = 0; q < o.q(); ++q) {
    const long double a = th[Order::a(q)], l = th[Order::lambda(q)];
    r += a * l / (l * l + w * w);
  }
  for (int s = 0; s < o.s(); ++s) {
    const long double b = th[o.b(s)], c = th[o.c(s)], al = th[o.alpha(s)], be = th[o.beta(s)];
    r += (b * al + c * (w + be)) / (al * al + (w + be) * (w + be)) + (b * al - c * (w - be)) / (al * al + (w - be) * (w - be));
  }
  return r;
}

DenseMinimum dense_minimum(const Order& o, const Eigen::VectorXd& th) {
  DenseMinimum m{re_g_long(o, th, 0.0L), 0.0};
  const auto visit = [&](double f) {
    const long double v = re_g_long(o, th, 2.0L * kPi * f);
    if (v < m.min_re) m.min_re = v, m.at_hz = f;
  };
  for (int i = 0; i <= 400000; ++i) visit(0.1 * std::pow(1e7, i / 400000.0));
  for (int s = 0; s < o.s(); ++s) {
    const double al = th[o.alpha(s)], be = std::abs(th[o.beta(s)]);
    for (int i = 0; i <= 40000; ++i) {
      const double w = be + al * (-40.0 + 80.0 * i / 40000.0);
      if (w > 0.0) visit(w / (2 * kPi));
    }
  }
  return m;
}

Eigen::VectorXd packed(const Order& o, std::initializer_list<double> values) {
  Eigen::VectorXd th(o.dim());
  REQUIRE(static_cast<Eigen::Index>(values.size()) == o.dim());
  Eigen::Index i = 0;
  for (double v : values) th[i++] = v;
  return th;
}

}  // namespace

TEST_CASE("certificate: a passive estimate whose own minimum was negative (Basotect rect_5cm, Q3S5) fails") {
  // The passive estimate of the default fit of samples/basotect_tuberlin/rect_5cm.csv (--live 100) at the
  // previous version: two real poles 23054 and 23277 s^-1 with residues +4.55e6 / -4.53e6 (a cancelling dipole).
  // The certificate reported min Re G = -6.7e-5 and passed. Reference (dense_minimum; confirmed with 50-digit
  // arithmetic outside the suite): Re G = -1.98e-4 at 1711.7 Hz, band 1710.94 - 1712.46 Hz, and two more
  // bands near 2156 Hz (-3.9e-8) and 9.75 kHz (-2.7e-7).
  const Order o(3, 5);
  const Eigen::VectorXd th = packed(
      o, {0.06373627643353622, -13755.465408967308, 6309.349034391055, 4553033.007453765, 23054.146544580446,
          -4534217.821705778, 23277.08667295218, 91.462887217482, -138.3833959901874, 294.5444732625157,
          4739.056078712158, -29.63633724899763, -141.839743721576, 323.7890395898215, 5041.602624652119,
          118.5918659363818, -90.41990640750268, 255.29021404210923, 6961.004090837595, -32.25119804769159,
          142.46826980910566, 176.11943716793525, 10605.580720453907, 3938.880670356452, -3635.526866632896,
          847.2890487012576, 15543.654892601928});
  const DenseMinimum ref = dense_minimum(o, th);
  REQUIRE(ref.min_re < -1.9e-4);
  const PassivityResult p = continuous_passivity(o, th.data());
  CHECK_FALSE(p.passive);
  CHECK_FALSE(is_passive(o, th.data()));
  // The reported minimum is the reference's within the polish (golden section to ~1e-13 of the cell: the
  // minimum of a smooth dip is exact to second order, so 1 % is loose) and at the same place within 0.1 Hz.
  CHECK(p.min_re == doctest::Approx(static_cast<double>(ref.min_re)).epsilon(0.01));
  CHECK(std::abs(p.min_at - ref.at_hz) < 0.1);
  REQUIRE(p.bands.size() == 3);
  CHECK(p.bands[0].lo == doctest::Approx(1710.94).epsilon(1e-5));
  CHECK(p.bands[0].hi == doctest::Approx(1712.46).epsilon(1e-5));
  CHECK(p.bands[1].at == doctest::Approx(2156.0).epsilon(1e-4));
  CHECK(p.bands[2].at == doctest::Approx(9760.0).epsilon(2e-3));
}

TEST_CASE("certificate: a 0.64 Hz band between two crossings with minimum -2.9e-8 (Basotect rect_10cm, Q5S5) fails") {
  // The passive estimate of rect_10cm's default fit at the previous version: two pairs 2 s^-1 apart at 1622 Hz
  // with cancelling residues (B -1830 / +1961). The certificate found both crossings, sampled between them at a
  // point where rounding left Re G positive, and passed with "2 crossing(s), 0 negative band(s)". Reference
  // (dense_minimum): Re G = -2.93e-8 at 1887.96 Hz, band 1887.64 - 1888.28 Hz.
  const Order o(5, 5);
  const Eigen::VectorXd th = packed(
      o, {3.3916277431744843e-09, 1253.7643914161508, 134.34470465913395, -2768.143805378561, 1574.7241360754726,
          164572.39009810204, 9834.898241708357, -226832.1646145248, 10906.802252624246, 67569.52575879073,
          12880.920304054984, 152.22545054891745, -180.5816241943942, 165.13243544180028, 3660.156458681562,
          212.52049858089254, -81.11470840816457, 613.902931273314, 7380.675363522816, 347.7762757779276,
          350.9189742325903, 773.0025661600203, 9963.65947084995, -1829.7058638952078, -2478.56374303221,
          30.640313441206875, 10189.368522019178, 1961.4092474942265, 2573.435424167542, 31.920352879469306,
          10191.202218804172});
  const DenseMinimum ref = dense_minimum(o, th);
  REQUIRE(ref.min_re < -2.9e-8);
  REQUIRE(ref.min_re > -3.0e-8);
  const PassivityResult p = continuous_passivity(o, th.data());
  CHECK_FALSE(p.passive);
  CHECK(p.min_re < 0.0);
  REQUIRE(p.bands.size() == 1);
  // The reference's edges are first/last negative points of a grid whose cell is 0.015 Hz here.
  CHECK(std::abs(p.bands[0].lo - 1887.64) < 0.02);
  CHECK(std::abs(p.bands[0].hi - 1888.28) < 0.02);
  CHECK(p.bands[0].min_re == doctest::Approx(static_cast<double>(ref.min_re)).epsilon(0.01));
}

TEST_CASE("certificate: a 1 Hz band just above the data, behind a cancelling dipole, fails the check") {
  // Data band 200 - 1600 Hz. G = 0.05 + a real dipole (lambda 15502 / 15568 s^-1, residues -3.34e6 / +3.36e6: the
  // shape of round_10cm's earlier passive estimate; its Re is >= 0 everywhere, 0.65 at 1650 Hz) + a narrow pair
  // at 1650 Hz (alpha = pi s^-1, half width 0.5 Hz) with B/alpha = -2 r0, r0 = Re(G_inf + dipole) there. Near
  // beta the pair's Re is (B/alpha)/(1 + x^2), x = (w - beta)/alpha, so Re G < 0 for |x| < 1: a band 2 alpha wide
  // = 1.0 Hz between two crossings 1 Hz apart, minimum -r0 (the pair's other half and the dipole's slope change
  // the edges by < 1e-4 Hz).
  const Order base(2, 0), o(2, 1);
  const double alpha = kPi, beta = 2 * kPi * 1650.0;
  const Eigen::VectorXd rest = packed(base, {0.05, -3.34e6, 15502.0, 3.36e6, 15568.0});
  const double r0 = static_cast<double>(re_g_long(base, rest, beta));
  const Eigen::VectorXd th = packed(o, {0.05, -3.34e6, 15502.0, 3.36e6, 15568.0, -2.0 * r0 * alpha, 0.0, alpha, beta});
  const DenseMinimum ref = dense_minimum(o, th);
  REQUIRE(static_cast<double>(ref.min_re) == doctest::Approx(-r0).epsilon(1e-3));
  REQUIRE(std::abs(ref.at_hz - 1650.0) < 0.01);
  CheckSubject s;
  s.origin = "synthetic";
  s.kind = "fit";
  s.surface = MultipoleSurface{o, th};
  s.data_f_min_hz = 200.0;
  s.data_f_max_hz = 1600.0;
  const CheckResult r = check_continuous_passivity(s);
  CHECK(r.status == Status::fail);
  const auto& d = std::get<PassivityDetails>(r.details);
  REQUIRE(d.test.bands.size() == 1);
  CHECK(d.places[0] == BandPlace::above);
  CHECK(d.test.bands[0].lo == doctest::Approx(1649.5).epsilon(1e-6));
  CHECK(d.test.bands[0].hi == doctest::Approx(1650.5).epsilon(1e-6));
}

TEST_CASE("certificate: on 60 random ill-conditioned models, passive only where a dense evaluation is >= 0") {
  // Random Q2S3 models with a cancelling real dipole (residues ~1e5-1e6, poles 0.1-1 % apart) and pairs of
  // quality factor 50-5000 with residues of both signs, shifted by G_inf so that min Re G lands near 0 (within
  // ±3e-4 of the dipole's in-band size): the regime where the earlier certificate erred. The certificate must
  // never pass a model whose reference minimum (dense_minimum) is below 0, and its reported minimum must never
  // be below 0 on a passing model. Seeded (Rng 44044) and sized so that both outcomes occur often (checked).
  Rng rng(44044);
  int passed = 0, failed = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Order o(2, 3);
    Eigen::VectorXd th(o.dim());
    const double lam = 2 * kPi * 1000.0 * std::pow(10.0, rng.uniform());
    const double amp = 1e5 * std::pow(10.0, rng.uniform());
    th[Order::a(0)] = -amp;
    th[Order::lambda(0)] = lam;
    th[Order::a(1)] = amp * (1.0 + 0.002 * rng.uniform());
    th[Order::lambda(1)] = lam * (1.0 + 0.001 + 0.009 * rng.uniform());
    for (int s = 0; s < o.s(); ++s) {
      th[o.beta(s)] = 2 * kPi * 200.0 * std::pow(50.0, rng.uniform());
      th[o.alpha(s)] = th[o.beta(s)] / (50.0 * std::pow(100.0, rng.uniform()));
      th[o.b(s)] = th[o.alpha(s)] * 0.05 * (rng.uniform() - 0.5);
      th[o.c(s)] = th[o.alpha(s)] * 0.05 * (rng.uniform() - 0.5);
    }
    th[Order::g_inf()] = 0.0;
    const DenseMinimum base = dense_minimum(o, th);
    th[Order::g_inf()] = static_cast<double>(-base.min_re) + 3e-4 * (rng.uniform() - 0.5);
    const DenseMinimum ref = dense_minimum(o, th);
    const PassivityResult p = continuous_passivity(o, th.data());
    CAPTURE(trial);
    CAPTURE(static_cast<double>(ref.min_re));
    if (ref.min_re < 0.0) CHECK_FALSE(p.passive);
    if (p.passive) CHECK(p.min_re >= 0.0);
    // Where the certificate finds a band, Re G is negative at its reported minimum in long double too.
    for (const auto& b : p.bands)
      if (std::isfinite(b.at)) CHECK(re_g_long(o, th, 2.0L * kPi * b.at) < 0.0L);
    (p.passive ? passed : failed) += 1;
  }
  CHECK(passed >= 10);
  CHECK(failed >= 10);
}

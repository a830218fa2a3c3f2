// SPDX-License-Identifier: MIT
// The pole search of the passive estimate (passivity/pole_refit.hpp, docs/passivity.md "Searching the poles").
// References, each independent of the code under test: central differences for the pole derivatives; exact
// data of a passive truth (the optimum is the truth, F = 0); and a one-pole case whose passive residues have a
// closed form (two linear constraints, solved by enumerating their active sets), minimised over the pole by
// brute force on a fine grid and golden-section refinement.
#include "core/rng.hpp"
#include "io/fit_file.hpp"
#include "model/multipole.hpp"
#include "model/passivity.hpp"
#include "model/residue_basis.hpp"
#include "passivity/passive_estimate.hpp"
#include "passivity/pole_refit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <fmt/format.h>

#include <cmath>
#include <limits>

using namespace admitgen;

namespace {

constexpr double kTwoPi = 6.283185307179586;

Eigen::ArrayXd log_omega(double f_lo, double f_hi, int n) {
  Eigen::ArrayXd w(n);
  for (int i = 0; i < n; ++i) w[i] = kTwoPi * f_lo * std::pow(f_hi / f_lo, i / double(n - 1));
  return w;
}

Measurement measurement(const Eigen::ArrayXd& omega, const Eigen::ArrayXcd& y) {
  Measurement m;
  m.f_hz = omega / kTwoPi;
  m.y = y;
  return m;
}

// ---- The one-pole reference: D = g + a/(λ0 + jω) with g < 0 (data passive in band, the model not) ----------

/// S(G∞, A) = Σ|D − G∞ − A/(λ + jω)|² at fixed λ, minimised over the face of the active set `face`
/// (0: none, 1: G∞ = 0, 2: G∞ + A/λ = 0, 3: both) by the normal equations of the remaining freedom.
/// Returns {S, G∞, A}.
Eigen::Vector3d face_minimum(const Eigen::ArrayXd& w, const Eigen::ArrayXcd& d, double lam, int face) {
  const Eigen::ArrayXcd phi = 1.0 / (lam + std::complex<double>(0.0, 1.0) * w);
  // Parameterise each face by one direction x ↦ (G∞, A) = x·v (faces 1, 2), two (face 0), none (face 3).
  Eigen::MatrixXd basis;
  if (face == 0) basis = Eigen::Matrix2d::Identity();
  if (face == 1) basis = Eigen::Vector2d(0.0, 1.0);
  if (face == 2) basis = Eigen::Vector2d(1.0, -lam);
  Eigen::Vector2d r = Eigen::Vector2d::Zero();
  if (basis.cols() > 0) {
    Eigen::MatrixXd a(2 * w.size(), basis.cols());
    Eigen::VectorXd b(2 * w.size());
    for (Eigen::Index i = 0; i < w.size(); ++i) {
      const Eigen::Vector2d re(1.0, phi[i].real()), im(0.0, phi[i].imag());
      a.row(i) = (basis.transpose() * re).transpose();
      a.row(w.size() + i) = (basis.transpose() * im).transpose();
      b[i] = d[i].real();
      b[w.size() + i] = d[i].imag();
    }
    r = basis * a.colPivHouseholderQr().solve(b);
  }
  const double s = (d - r[0] - r[1] * phi).abs2().sum();
  return {s, r[0], r[1]};
}

/// F(λ): the passive one-pole model closest to D. Re G(jω) = G∞ + Aλ/(λ² + ω²) is monotone in ω, so
/// Re G ≥ 0 for every ω ⇔ G∞ ≥ 0 and G∞ + A/λ ≥ 0; the convex problem's minimum is the smallest S among the
/// feasible face minima.
double passive_one_pole(const Eigen::ArrayXd& w, const Eigen::ArrayXcd& d, double lam) {
  double best = std::numeric_limits<double>::infinity();
  for (int face = 0; face < 4; ++face) {
    const Eigen::Vector3d m = face_minimum(w, d, lam, face);
    const double tol = 1e-12 * (1.0 + std::abs(m[1]) + std::abs(m[2] / lam));
    if (m[1] >= -tol && m[1] + m[2] / lam >= -tol) best = std::min(best, m[0]);
  }
  return best;
}

/// min over λ of F by brute force (a log grid of 4001 points over four decades) and golden-section refinement.
std::pair<double, double> brute_force_minimum(const Eigen::ArrayXd& w, const Eigen::ArrayXcd& d, double lam0) {
  double best_u = 0.0, best_f = std::numeric_limits<double>::infinity();
  const double lo = std::log(lam0 / 100.0), hi = std::log(lam0 * 100.0);
  constexpr int kGrid = 4001;
  for (int i = 0; i < kGrid; ++i) {
    const double u = lo + (hi - lo) * i / (kGrid - 1);
    const double f = passive_one_pole(w, d, std::exp(u));
    if (f < best_f) best_f = f, best_u = u;
  }
  const double h = (hi - lo) / (kGrid - 1);
  double a = best_u - h, b = best_u + h;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 100; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    (passive_one_pole(w, d, std::exp(x1)) < passive_one_pole(w, d, std::exp(x2)) ? b : a) = (x1 + x2) / 2.0;
  }
  const double u = (a + b) / 2.0;
  return {passive_one_pole(w, d, std::exp(u)), std::exp(u)};
}

}  // namespace

TEST_CASE("pole derivatives: agree with central differences of the model, narrow pairs and beta = 0 included") {
  // h = 1e-6 of each term's own rate (λ, or α for both α and β of a pair): the truncation error is
  // (h/|x + jω|)² ≤ 1e-12 and rounding ε·|G|/h ≈ 2e-10 of a column's scale, so 1e-7 of the column's largest
  // value bounds the difference with a wide margin.
  const Order order(1, 3);
  Eigen::VectorXd th(order.dim());
  th << 0.4, 3000.0, 2500.0,             // G∞; A, λ
      0.8, -0.3, 2.0, kTwoPi * 1000.0,  // a pair 0.3 Hz wide at 1 kHz
      200.0, 50.0, 900.0, 0.0,          // β = 0
      -40.0, 300.0, 4000.0, 20000.0;    // a broad pair
  Eigen::ArrayXd w(9);
  w << 0.0, 10.0, 900.0, kTwoPi * 1000.0 - 1.0, kTwoPi * 1000.0, 20000.0, 1e5, 1e7,
      std::numeric_limits<double>::infinity();
  const ResidueBasis d = pole_derivatives(order, th, w);
  REQUIRE(d.re.cols() == order.buffers());
  const int poles[] = {Order::lambda(0), order.alpha(0), order.beta(0), order.alpha(1), order.beta(1), order.alpha(2),
                       order.beta(2)};
  const double rates[] = {th[Order::lambda(0)], th[order.alpha(0)], th[order.alpha(0)], th[order.alpha(1)],
                          th[order.alpha(1)], th[order.alpha(2)], th[order.alpha(2)]};
  for (int k = 0; k < order.buffers(); ++k) {
    const double h = 1e-6 * rates[k];
    Eigen::VectorXd up = th, down = th;
    up[poles[k]] += h;
    down[poles[k]] -= h;
    // Divided by the step as represented (β + h rounds to a multiple of ulp(β), 1e-12 of β = 6283).
    const Eigen::ArrayXcd fd = (evaluate_multipole(order, up, w.head(8)) - evaluate_multipole(order, down, w.head(8))) /
                               (up[poles[k]] - down[poles[k]]);
    const double scale = fd.abs().maxCoeff();
    CAPTURE(k);
    for (Eigen::Index i = 0; i < 8; ++i) {
      CAPTURE(i);
      CHECK(std::abs(d.re(i, k) - fd[i].real()) <= 1e-7 * scale);
      CHECK(std::abs(d.im(i, k) - fd[i].imag()) <= 1e-7 * scale);
    }
    CHECK(d.re(8, k) == 0.0);  // ω = ∞: no pole term
    CHECK(d.im(8, k) == 0.0);
  }
}

TEST_CASE("pole refit: exact data of a passive truth lead back to the truth from poles 10-25 % off") {
  // The optimum of F is the truth itself (F = 0; Re G ≥ 0.2 everywhere, so no constraint binds).
  const Order order(1, 1);
  Eigen::VectorXd truth(order.dim());
  truth << 0.2, 3000.0, 4000.0, 500.0, -100.0, 1500.0, 6000.0;
  REQUIRE(continuous_passivity(order, truth.data()).passive);
  const Eigen::ArrayXd w = log_omega(100.0, 4000.0, 200);
  const Eigen::ArrayXcd y = evaluate_multipole(order, truth, w);
  Eigen::VectorXd start = truth;
  start[Order::lambda(0)] *= 1.2;
  start[order.alpha(0)] *= 0.8;
  start[order.beta(0)] *= 1.1;
  const passivity::ResidueTarget target{w, y, Eigen::ArrayXd::Ones(w.size())};
  const auto refit = passivity::refit_poles(order, start, target, 60);
  MESSAGE("F " << refit.start_sum_squares << " -> " << refit.sum_squares << " in " << refit.steps << " steps");
  CHECK(refit.start_sum_squares > 1e-2);
  // F ≤ 1e-20 ‖y‖²: at the truth Gauss–Newton converges quadratically, and the stop rule (gain below 1e-7 of
  // F twice) cannot fire while F still falls by orders of magnitude per step.
  CHECK(refit.sum_squares <= 1e-20 * y.abs2().sum());
  for (int i = 0; i < order.dim(); ++i) {
    CAPTURE(i);
    CHECK(refit.theta[i] == doctest::Approx(truth[i]).epsilon(1e-6));
  }
}

TEST_CASE("pole refit: one pole, passive data fitted best by a non-passive model: the brute-force optimum") {
  // D = −0.3 + 1.3 λ0/(λ0 + jω), λ0 = 2π·1 kHz: Re D = −0.3 + 1.3 λ0²/(λ0² + ω²) > 0 below 1.83 kHz, so the data
  // (100-1500 Hz) are passive while their exact model is not (G∞ = −0.3): the situation of the bundled
  // Basotect files in one pole. The passive optimum moves λ.
  const Order order(1, 0);
  const double lam0 = kTwoPi * 1000.0;
  const Eigen::ArrayXd w = log_omega(100.0, 1500.0, 120);
  const Eigen::ArrayXcd d = -0.3 + 1.3 * lam0 / (lam0 + std::complex<double>(0.0, 1.0) * w);
  REQUIRE((d.real() > 0.0).all());
  const auto [f_star, lam_star] = brute_force_minimum(w, d, lam0);
  const double f_fixed = passive_one_pole(w, d, lam0);
  MESSAGE("brute force: F* = " << f_star << " at lambda = " << lam_star << " (F at the truth's lambda " << f_fixed << ")");
  REQUIRE(f_star < 0.5 * f_fixed);  // not vacuous: moving the pole matters
  Eigen::VectorXd start(order.dim());
  start << -0.3, 1.3 * lam0, lam0;  // the (non-passive) best fit
  const passivity::ResidueTarget target{w, d, Eigen::ArrayXd::Ones(w.size())};
  const auto refit = passivity::refit_poles(order, start, target, 60);
  MESSAGE("refit: F " << refit.start_sum_squares << " -> " << refit.sum_squares << " at lambda = "
                      << refit.theta[Order::lambda(0)] << " in " << refit.steps << " steps");
  // The start's F is the reference's at λ0 (the same convex problem; the refit's margin 2e-9·max|D| moves it by
  // less than 1e-6 of F).
  CHECK(refit.start_sum_squares == doctest::Approx(f_fixed).epsilon(1e-6));
  // The refit stops once a step gains less than 1e-7 of F, twice; near the minimum F is quadratic in ln λ, so
  // the gap left is of the order of the last gains: 1e-5 of F bounds it. The margin keeps F above F*.
  CHECK(refit.sum_squares <= f_star * (1.0 + 1e-5));
  CHECK(refit.sum_squares >= f_star * (1.0 - 1e-6));
  CHECK(refit.theta[Order::lambda(0)] == doctest::Approx(lam_star).epsilon(1e-2));
  // Refits are deterministic: the same bits again.
  const auto again = passivity::refit_poles(order, start, target, 60);
  CHECK(again.theta == refit.theta);
  // And the passive estimate built on it is certified and reaches the same optimum (its final residues come
  // from the certified solve, at the same margin).
  const auto e = passivity::passive_estimate(measurement(w, d), order, {start}, DataCount::two_per_point);
  CHECK(e.certified);
  CHECK(e.poles_searched);
  CHECK(continuous_passivity(order, e.theta.data()).passive);
  CHECK(e.relative_rms_residual == doctest::Approx(std::sqrt(f_star / d.abs2().sum())).epsilon(1e-5));
  CHECK(e.sampled_poles_relative_rms_residual == doctest::Approx(std::sqrt(f_fixed / d.abs2().sum())).epsilon(1e-6));
}

TEST_CASE("passive estimate: where passivity costs more than 1.25x the best sample's residual, it says so and why") {
  // The same one-pole data continued to 4 kHz, where Re D < 0 (above 1.83 kHz), with noise of std 1e-3 on each
  // part (seeded): no passive model can follow them, and the estimate must say how much that costs.
  const Order order(1, 0);
  const double lam0 = kTwoPi * 1000.0;
  const Eigen::ArrayXd w = log_omega(100.0, 4000.0, 150);
  Eigen::ArrayXcd d = -0.3 + 1.3 * lam0 / (lam0 + std::complex<double>(0.0, 1.0) * w);
  Rng rng(34);
  for (Eigen::Index i = 0; i < d.size(); ++i) d[i] += std::complex<double>(1e-3 * rng.normal(), 1e-3 * rng.normal());
  Eigen::VectorXd best(order.dim());
  best << -0.3, 1.3 * lam0, lam0;
  const auto e = passivity::passive_estimate(measurement(w, d), order, {best}, DataCount::two_per_point);
  CHECK(e.certified);
  REQUIRE(e.relative_rms_residual > passivity::PassiveEstimate::kCostRatio * e.best_sample_relative_rms_residual);
  CHECK(e.cost_reason.find("not passive at") != std::string::npos);        // the data
  CHECK(e.cost_reason.find("G_inf = -0.3 < 0") != std::string::npos);      // the best sample
  const std::string warning = passivity::passivity_cost_warning(order, e);
  MESSAGE(warning);
  CHECK(warning.find("passivity costs") != std::string::npos);
  CHECK(warning.find(fmt::format("{:.4g} nats", e.best_sample_log_likelihood - e.log_likelihood)) != std::string::npos);
}

TEST_CASE("pole refit: canonical terms leave G unchanged and report beta >= 0, lambda and beta ascending") {
  const Order order(2, 2);
  Eigen::VectorXd th(order.dim());
  th << 0.3, 900.0, 5000.0, 200.0, 800.0,  // λ out of order
      10.0, 40.0, 300.0, -7000.0,           // β < 0, and above the next pair's |β|
      5.0, -3.0, 200.0, 2000.0;
  const Eigen::VectorXd c = passivity::canonical_terms(order, th);
  CHECK(c[Order::lambda(0)] == 800.0);
  CHECK(c[Order::lambda(1)] == 5000.0);
  CHECK(c[order.beta(0)] == 2000.0);
  CHECK(c[order.beta(1)] == 7000.0);
  CHECK(c[order.c(1)] == -40.0);
  const Eigen::ArrayXd w = log_omega(10.0, 10000.0, 50);
  // The same five terms summed in another order differ by a few ε of the largest term, which is within 10×
  // of max|G| here: 1e-12 of max|G| bounds that with a wide margin.
  const Eigen::ArrayXcd g = evaluate_multipole(order, th, w);
  CHECK((evaluate_multipole(order, c, w) - g).abs().maxCoeff() <= 1e-12 * g.abs().maxCoeff());
}

TEST_CASE("fit.json: the pole search's keys read and write back byte for byte") {
  // The golden fit holds a searched passive estimate (sampled_poles_relative_rms_residual, pole_search_steps);
  // passivity_cost is added by hand.
  const std::string golden = test::read_text(test::sample("../tests/golden/expected/fit.json"));
  REQUIRE(golden.find("\"pole_search_steps\"") != std::string::npos);
  CHECK(io::fit_text(io::parse_fit(golden, "golden")) == golden);
  const std::string key = "\"pole_search_steps\": ";
  const auto at = golden.find('\n', golden.find(key));
  // passivity_cost follows pole_search_steps (and precedes the conditioning keys, when present).
  const bool last = golden[at - 1] != ',';
  const std::string edited = last ? golden.substr(0, at) + ",\n        \"passivity_cost\": \"why\"" + golden.substr(at)
                                  : golden.substr(0, at) + "\n        \"passivity_cost\": \"why\"," + golden.substr(at);
  const FitRecord fit = io::parse_fit(edited, "edited");
  int costs = 0;
  for (const auto& m : fit.models) costs += m.passive_estimate && m.passive_estimate->passivity_cost == std::string("why");
  CHECK(costs == 1);
  CHECK(io::fit_text(fit) == edited);
}

TEST_CASE("pole refit: coincident poles (a rank-deficient basis) are refused, never a crash") {
  // Two real poles at the same λ make the residue basis rank-deficient: the refit does not start from them, and
  // the passive estimate either certifies a result or reports it as not certified.
  const Order order(2, 0);
  const double lam0 = kTwoPi * 1000.0;
  const Eigen::ArrayXd w = log_omega(100.0, 1500.0, 80);
  const Eigen::ArrayXcd d = -0.3 + 1.3 * lam0 / (lam0 + std::complex<double>(0.0, 1.0) * w);
  Eigen::VectorXd start(order.dim());
  start << -0.3, 0.65 * lam0, lam0, 0.65 * lam0, lam0;
  const passivity::ResidueTarget target{w, d, Eigen::ArrayXd::Ones(w.size())};
  const auto refit = passivity::refit_poles(order, start, target, 60);
  CHECK(refit.accepted == 0);
  CHECK(std::isinf(refit.sum_squares));
  const auto e = passivity::passive_estimate(measurement(w, d), order, {start}, DataCount::two_per_point);
  CHECK(e.certified == continuous_passivity(order, e.theta.data()).passive);
}

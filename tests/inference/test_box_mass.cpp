// SPDX-License-Identifier: MIT
// The box mass of the conditional t of the residues (docs/method.md, "Truncation by the residue box" and
// "The box mass the sampler uses") against independent references: the box-constrained least squares
// against an exhaustive enumeration of active sets, and the upper bounds P̃, P_up and the GHK estimate
// against brute-force Monte Carlo hit counts of untruncated draws.
#include "core/rng.hpp"
#include "data/csv_reader.hpp"
#include "inference/box_least_squares.hpp"
#include "inference/pole_space.hpp"
#include "inference/poles_sampler.hpp"
#include "inference/posterior.hpp"
#include "inference/residue_draws.hpp"
#include "inference/residue_marginal.hpp"
#include "test_support.hpp"

#include <Eigen/Eigenvalues>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

double objective(const Eigen::MatrixXd& m, const Eigen::VectorXd& c, const Eigen::VectorXd& x) {
  return (x - c).dot(m * (x - c));
}

/// The minimum over the box by enumeration: every assignment of each coordinate to free / lower / upper
/// (3^p), the free ones solved with the others fixed, the best admissible one kept.
double exhaustive_minimum(const Eigen::MatrixXd& m, const Eigen::VectorXd& c, const Eigen::VectorXd& lo,
                          const Eigen::VectorXd& hi) {
  const Eigen::Index p = c.size();
  long patterns = 1;
  for (Eigen::Index k = 0; k < p; ++k) patterns *= 3;
  double best = std::numeric_limits<double>::infinity();
  for (long code = 0; code < patterns; ++code) {
    Eigen::VectorXd x = c;
    std::vector<Eigen::Index> fr;
    long rest = code;
    for (Eigen::Index k = 0; k < p; ++k, rest /= 3) {
      if (rest % 3 == 0) fr.push_back(k);
      if (rest % 3 == 1) x[k] = lo[k];
      if (rest % 3 == 2) x[k] = hi[k];
    }
    const Eigen::Index f = static_cast<Eigen::Index>(fr.size());
    if (f > 0) {
      Eigen::MatrixXd mff(f, f);
      Eigen::VectorXd rhs = Eigen::VectorXd::Zero(f);
      for (Eigen::Index i = 0; i < f; ++i) {
        for (Eigen::Index j = 0; j < f; ++j) mff(i, j) = m(fr[static_cast<std::size_t>(i)], fr[static_cast<std::size_t>(j)]);
        for (Eigen::Index k = 0; k < p; ++k) rhs[i] -= m(fr[static_cast<std::size_t>(i)], k) * (x[k] - c[k]);
      }
      // rhs included the free coordinates at x = c (zero), so this is −M_FB (x_B − c_B).
      const Eigen::VectorXd y = mff.ldlt().solve(rhs);
      for (Eigen::Index i = 0; i < f; ++i) x[fr[static_cast<std::size_t>(i)]] = c[fr[static_cast<std::size_t>(i)]] + y[i];
    }
    if ((x.array() < lo.array() - 1e-12).any() || (x.array() > hi.array() + 1e-12).any()) continue;
    best = std::min(best, objective(m, c, x));
  }
  return best;
}

/// The mean of n GHK replicates of P_box and its standard error.
std::pair<double, double> ghk_mean(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                   int n, Rng& rng) {
  const BoxMassEstimate e = estimate_box_mass(c, lo, hi, n, rng);
  return {e.mean, std::sqrt(e.sample_variance / n)};
}

}  // namespace

TEST_CASE("box least squares: equals the exhaustive active-set enumeration (p = 1..7, condition up to 1e8)") {
  // 60 random problems per p: M = Q diag(10^{U(−4, 4)}) Qᵀ (condition numbers up to 1e8, as the Jacobi-scaled
  // normal equations of nearly coinciding poles), the box [−1, 1]^p shifted, the centre ±3 outside it in
  // most coordinates. Tolerance: relative 1e-9 of the objective (each solution is one LDLT solve of a
  // system whose condition is at most 1e8: error ~ 1e8 · 1e-16 relative).
  Rng rng(11);
  for (int p = 1; p <= 7; ++p)
    for (int trial = 0; trial < 60; ++trial) {
      Eigen::MatrixXd g(p, p);
      for (Eigen::Index i = 0; i < g.size(); ++i) g.data()[i] = rng.normal();
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
      const Eigen::MatrixXd q = qr.householderQ();
      Eigen::VectorXd ev(p);
      for (int k = 0; k < p; ++k) ev[k] = std::pow(10.0, -4.0 + 8.0 * rng.uniform());
      const Eigen::MatrixXd m = q * ev.asDiagonal() * q.transpose();
      Eigen::VectorXd lo(p), hi(p), c(p);
      for (int k = 0; k < p; ++k) {
        const double shift = rng.normal();
        lo[k] = -1.0 + shift;
        hi[k] = 1.0 + shift;
        c[k] = 6.0 * rng.uniform() - 3.0;
      }
      bool converged = false;
      const Eigen::VectorXd x = box_least_squares(m, c, lo, hi, &converged);
      const double reference = exhaustive_minimum(m, c, lo, hi);
      INFO("p = ", p, ", trial ", trial, ": active set ", objective(m, c, x), ", enumeration ", reference);
      CHECK(converged);
      CHECK((x.array() >= lo.array()).all());
      CHECK((x.array() <= hi.array()).all());
      CHECK(objective(m, c, x) <= reference * (1.0 + 1e-9) + 1e-300);
    }
}

TEST_CASE("box mass: P_sampled and P_up bound the Monte Carlo box mass, GHK equals it (reference file, Q3S0, Q1S2)") {
  // Poles drawn from the Table 1 prior on the reference file; cases where the box cuts the conditional t
  // (P_lo < P_up) and, for the multi-face check, where r̂ lies outside the box in two or more coordinates.
  // Brute force: N = 20000 untruncated draws, P_mc = h/N, standard error √(P(1 − P)/N) (P from (h+1)/(N+2)).
  // GHK: 2000 replicates, its sample standard error. Each check allows 5 combined standard errors
  // (one-sided normal tail 3e-7; with ~300 checks the chance of a false failure is below 1e-4) and is
  // made only where h ≥ 20 (the binomial error is then roughly normal).
  ReadOptions read;
  const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), read);
  Rng rng(5);
  int checked = 0, multi_face = 0;
  double worst_gap = 0.0;  // max ln(P̃/P_box) over the multi-face cases with a resolvable P_box
  for (const Order order : {Order(3, 0), Order(1, 2)}) {
    const PriorRanges priors = PriorRanges::table1();
    const PoleTransform transform(order, priors, true);
    const ResidueMarginal marginal(data, order, DataCount::two_per_point, priors);
    std::vector<double> u(static_cast<std::size_t>(transform.dim())), psi(u.size());
    for (int trial = 0; trial < 400 && checked < 80 * (order.q() == 3 ? 1 : 2); ++trial) {
      for (double& x : u) x = rng.uniform();
      transform(u.data(), psi.data());
      const ResidueConditional& cref = marginal.conditional(psi.data());
      if (!cref.valid || !(-std::expm1(cref.log_p_lo - cref.log_p_up) > 1e-9)) continue;
      const ResidueConditional c = cref;  // the marginal's buffer is reused by later calls
      const Eigen::VectorXd &lo = marginal.box_lo(), &hi = marginal.box_hi();
      constexpr long kDraws = 20000;
      long hits = 0;
      for (long d = 0; d < kDraws; ++d) hits += in_residue_box(untruncated_residue_draw(c, rng), lo, hi) ? 1 : 0;
      const auto [p_ghk, se_ghk] = ghk_mean(c, lo, hi, 2000, rng);
      const double p_mc = static_cast<double>(hits) / kDraws, p_smooth = (hits + 1.0) / (kDraws + 2.0);
      const double se_mc = std::sqrt(p_smooth * (1.0 - p_smooth) / kDraws);
      int outside = 0;
      for (Eigen::Index k = 0; k < c.mean.size(); ++k) outside += (c.mean[k] < lo[k] || c.mean[k] > hi[k]) ? 1 : 0;
      INFO(order.name(), " trial ", trial, ": hits ", hits, ", P_mc ", p_mc, ", GHK ", p_ghk, " ± ", se_ghk,
           ", P_sampled ", std::exp(c.log_p_sampled), ", P_up ", std::exp(c.log_p_up), ", P_lo ",
           std::exp(c.log_p_lo), ", coordinates outside ", outside);
      // GHK is unbiased whatever P_box: it never exceeds the bounds by more than its error.
      CHECK(p_ghk <= std::exp(c.log_p_sampled) + 5.0 * se_ghk + 1e-300);
      CHECK(p_ghk >= std::exp(c.log_p_lo) - 5.0 * se_ghk);
      if (hits < 20) continue;
      ++checked;
      CHECK(std::abs(p_ghk - p_mc) <= 5.0 * std::hypot(se_ghk, se_mc));
      CHECK(std::exp(c.log_p_sampled) >= p_mc - 5.0 * se_mc);
      CHECK(std::exp(c.log_p_up) >= p_mc - 5.0 * se_mc);
      if (outside >= 2) {
        ++multi_face;
        worst_gap = std::max(worst_gap, c.log_p_sampled - std::log(p_mc));
      }
    }
  }
  MESSAGE("cases checked against Monte Carlo: ", checked, ", with r̂ outside in two or more coordinates: ", multi_face,
          ", largest ln(P_sampled/P_box) there: ", worst_gap);
  CHECK(checked >= 40);
  CHECK(multi_face >= 5);
}

TEST_CASE("box mass: P_sampled stays above P_box far in the tail, r̂ outside the box (Q3S2 posterior, reference file)") {
  // An over-complete order: its posterior holds poles whose r̂ lies outside the box while M̃ has eigenvalues
  // spread over many decades, P_box e^-5 … e^-20, far below what hit counts resolve. Reference: the GHK mean
  // of 4000 replicates (checked against hit counts above where those resolve). P_sampled is an upper bound
  // (docs/method.md, "The box mass the sampler uses"), so it may not lie below P̂ by more than 5 of its
  // standard errors (one-sided 3e-7 per point). Slab directions that are B-orthogonal only to ‖B‖ε broke
  // this by up to 7 nats at such points. The pole run: 50 live points, seed 3 (about 1 s).
  ReadOptions read;
  const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), read);
  const Order order(3, 2);
  const PriorRanges priors = PriorRanges::table1();
  NestedSettings settings;
  settings.live = 50;
  settings.seed = 3;
  const PolesRun poles = run_poles_sampler(data, order, priors, true, DataCount::two_per_point, settings, 7);
  const ResidueMarginal marginal(data, order, DataCount::two_per_point, priors);
  const Eigen::ArrayXd weight = posterior_weights(poles.run);
  std::vector<std::size_t> by_weight(poles.run.size());
  std::iota(by_weight.begin(), by_weight.end(), std::size_t{0});
  std::sort(by_weight.begin(), by_weight.end(), [&](std::size_t a, std::size_t b) {
    return weight[static_cast<Eigen::Index>(a)] > weight[static_cast<Eigen::Index>(b)];
  });
  const std::vector<int> pole_index = pole_indices(order);
  Rng rng(23);
  int checked = 0;
  double worst = -std::numeric_limits<double>::infinity();  // max ln(P̂/P_sampled)
  for (std::size_t i : by_weight) {
    if (checked >= 40) break;
    std::vector<double> psi;
    for (int k : pole_index) psi.push_back(poles.run.point(i)[k]);
    const ResidueConditional c = marginal.conditional(psi.data());
    const Eigen::VectorXd &lo = marginal.box_lo(), &hi = marginal.box_hi();
    if (!c.valid || !(-std::expm1(c.log_p_lo - c.log_p_up) > 1e-9) || in_residue_box(c.mean, lo, hi)) continue;
    const auto [p_ghk, se] = ghk_mean(c, lo, hi, 4000, rng);
    ++checked;
    worst = std::max(worst, std::log(p_ghk) - c.log_p_sampled);
    INFO("point ", i, ": GHK ", p_ghk, " ± ", se, ", P_sampled ", std::exp(c.log_p_sampled), ", P_up ",
         std::exp(c.log_p_up));
    CHECK(std::exp(c.log_p_sampled) >= p_ghk - 5.0 * se);
  }
  MESSAGE("points checked: ", checked, ", largest ln(GHK/P_sampled): ", worst);
  CHECK(checked >= 20);
}

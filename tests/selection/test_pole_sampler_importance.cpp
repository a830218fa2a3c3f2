// SPDX-License-Identifier: MIT
// The pole sampler (inference/poles_sampler.hpp) against an independent estimate of the same evidence:
// importance sampling over the poles, Z = E_q[L(ψ) π(ψ)/q(ψ)], with L(ψ) the residue-marginal likelihood
// (checked against quadrature over r in test_residue_marginal.cpp) and the box mass P_box estimated without
// bias from untruncated t draws. No nested sampling is involved in the reference, so a bias of the sampler's
// exploration shows up here (docs/method.md, "Status of the pole sampler"); the full sampler cannot serve
// as the reference for these orders, it comes out high at a few hundred live points (same section).
//
// Proposal q over the unreduced prior (Z does not depend on the symmetry reduction): λ ~ t_3(57000, 10000);
// the pair the data need ~ t_3(1530, 20) × t_3(±10060, 20) (either sign, and for S = 2 either slot), the
// extra pair of Q1S2 uniform on its prior. Its error is the sample standard error of the mean of the ratios.
// Tolerance: 3 combined standard errors √(e_ns² + e_is²) (99.7 % for two independent estimates).
// Sizes: pole sampler with 300 live points, seed 1 (with the box mass sampled: 200, seed 2); 20000 proposal draws, 2000 box draws where P_box is
// not known to 1e-9 (each case a few seconds on one core).
#include "core/rng.hpp"
#include "data/csv_reader.hpp"
#include "inference/evidence.hpp"
#include "inference/likelihood.hpp"
#include "inference/pole_space.hpp"
#include "model/residue_basis.hpp"
#include "inference/poles_sampler.hpp"
#include "inference/residue_draws.hpp"
#include "inference/residue_marginal.hpp"
#include "pole_importance.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

using namespace admitgen;

namespace {

constexpr double kNu = 3.0;  // proposal t degrees of freedom

double t_log_density(double x, double centre, double scale) {
  const double z = (x - centre) / scale;
  return std::lgamma(0.5 * (kNu + 1.0)) - std::lgamma(0.5 * kNu) - 0.5 * std::log(kNu * EIGEN_PI) - std::log(scale) -
         0.5 * (kNu + 1.0) * std::log1p(z * z / kNu);
}

double t_draw(Rng& rng, double centre, double scale) {
  const double z = rng.normal();
  double w = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double g = rng.normal();
    w += g * g;
  }
  return centre + scale * z / std::sqrt(w / kNu);
}

using Estimate = test::ImportanceEstimate;

/// Importance-sampling ln Z for Q1S1 or Q1S2 (Table 1 pole ranges; residue ranges from `priors`).
Estimate importance_log_z(const Measurement& data, const Order& order, const PriorRanges& priors, long draws) {
  const ResidueMarginal marginal(data, order, DataCount::two_per_point, priors);
  const int pairs = order.s();
  const double pair_area = priors.alpha.width() * priors.beta.width();
  const double log_prior = -std::log(priors.lambda.width()) - pairs * std::log(pair_area);
  constexpr double kPairScale = 20.0;
  Rng rng(11);
  std::vector<double> log_ratio;
  std::vector<double> psi(static_cast<std::size_t>(1 + 2 * pairs));
  const auto in_pair_prior = [&](double a, double b) {
    return a >= priors.alpha.lo && a <= priors.alpha.hi && b >= priors.beta.lo && b <= priors.beta.hi;
  };
  for (long i = 0; i < draws; ++i) {
    psi[0] = t_draw(rng, 57000.0, 10000.0);
    const int slot = pairs == 2 && rng.uniform() < 0.5 ? 1 : 0;
    const double sign = rng.uniform() < 0.5 ? 1.0 : -1.0;
    const std::size_t t = static_cast<std::size_t>(1 + 2 * slot), x = static_cast<std::size_t>(3 - 2 * slot);
    psi[t] = t_draw(rng, 1530.0, kPairScale);
    psi[t + 1] = sign * t_draw(rng, 10060.0, kPairScale);
    if (pairs == 2) {
      psi[x] = priors.alpha.lo + priors.alpha.width() * rng.uniform();
      psi[x + 1] = priors.beta.lo + priors.beta.width() * rng.uniform();
    }
    // q(ψ): the mixture over slot and sign (the uniform factor only where the other pair is in its prior).
    double log_mix = -std::numeric_limits<double>::infinity();
    for (int sl = 0; sl < pairs; ++sl) {
      const std::size_t tt = static_cast<std::size_t>(1 + 2 * sl), xx = static_cast<std::size_t>(3 - 2 * sl);
      if (pairs == 2 && !in_pair_prior(psi[xx], psi[xx + 1])) continue;
      for (const double sg : {1.0, -1.0})
        log_mix = log_add_exp(log_mix, -std::log(2.0 * pairs) + t_log_density(psi[tt], 1530.0, kPairScale) +
                                       t_log_density(psi[tt + 1], sg * 10060.0, kPairScale) -
                                       (pairs == 2 ? std::log(pair_area) : 0.0));
    }
    const double log_q = t_log_density(psi[0], 57000.0, 10000.0) + log_mix;
    bool inside = psi[0] >= priors.lambda.lo && psi[0] <= priors.lambda.hi;
    for (int s = 0; s < pairs; ++s)
      inside = inside && in_pair_prior(psi[static_cast<std::size_t>(1 + 2 * s)], psi[static_cast<std::size_t>(2 + 2 * s)]);
    const ResidueConditional* c = inside ? &marginal.conditional(psi.data()) : nullptr;
    if (c == nullptr || !c->valid) {
      log_ratio.push_back(-std::numeric_limits<double>::infinity());
      continue;
    }
    log_ratio.push_back(c->log_marginal - c->log_p_sampled + test::log_box_mass(*c, marginal, 2000, rng) + log_prior -
                        log_q);
  }
  return test::mean_of_ratios(log_ratio);
}

Measurement reference_file() {
  return read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
}

void check_against_importance(const Order& order, const PriorRanges& priors) {
  const Measurement data = reference_file();
  const Estimate reference = importance_log_z(data, order, priors, 20000);
  FitSettings settings;
  settings.priors = priors;
  settings.sampler.live = 300;
  settings.sampler_kind = SamplerKind::poles;
  const ModelResult poles = fit_order(data, order, settings);
  MESSAGE(order.name(), " (G_inf ≤ ", priors.g_inf.hi, "): pole sampler ", poles.run.log_z, " ± ", poles.run.log_z_error,
          " (", poles.sampler, ", box correction ", poles.truncation_correction, "), importance sampling ",
          reference.log_z, " ± ", reference.error);
  CHECK(poles.sampler == "poles_analytic_residues");
  CHECK(std::abs(poles.run.log_z - reference.log_z) <= 3.0 * std::hypot(poles.run.log_z_error, reference.error));
  // The same evidence with the box mass sampled as coordinates (the fallback of fit_order): exact by
  // construction, so the same tolerance; 200 live points, seed 2.
  NestedSettings sampled = settings.sampler;
  sampled.live = 200;
  sampled.seed = 2;
  const PolesRun box = run_poles_sampler(data, order, priors, true, DataCount::two_per_point, sampled, 3, {},
                                         BoxMassMethod::sampled);
  MESSAGE(order.name(), " (G_inf ≤ ", priors.g_inf.hi, "): box mass sampled ", box.run.log_z, " ± ", box.run.log_z_error,
          " (", box.run.calls, " calls)");
  CHECK(box.box_mass == BoxMassMethod::sampled);
  CHECK(std::abs(box.run.log_z - reference.log_z) <= 3.0 * std::hypot(box.run.log_z_error, reference.error));
  // Its posterior is complete: every point's residues lie in the box and its ln L is that of its own θ.
  const Likelihood likelihood(data, order, DataCount::two_per_point);
  Eigen::VectorXd lo, hi;
  residue_box(order, priors, lo, hi);
  const std::vector<int> residues_at = residue_indices(order);
  int outside = 0;
  for (std::size_t i = 0; i + 1 < box.run.size(); ++i) {
    const double* theta = box.run.point(i);
    Eigen::VectorXd r(lo.size());
    for (std::size_t j = 0; j < residues_at.size(); ++j) r[static_cast<Eigen::Index>(j)] = theta[residues_at[j]];
    outside += in_residue_box(r, lo, hi) ? 0 : 1;
    CHECK(box.run.log_likelihood[i] == likelihood(theta));
  }
  CHECK(outside == 0);
}

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("pole sampler: ln Z equals importance sampling over the poles (Q1S1, Q1S2, G_inf box cutting the posterior)") {
    PriorRanges table1 = PriorRanges::table1();
    check_against_importance(Order(1, 1), table1);
    check_against_importance(Order(1, 2), table1);
    // G_inf's posterior (0.49 ± 0.02) cut by its box at 0.468: the conditional t of r is truncated.
    PriorRanges cut = table1;
    cut.g_inf.hi = 0.468;
    check_against_importance(Order(1, 1), cut);
  }

  TEST_CASE("pole sampler: 24 seeds scatter as reported and centre on importance sampling (Q1S1, Q1S2)") {
    // Seeds 100-123; Q1S1 with 100 live points, Q1S2 with 300. The sample standard deviation of 24 values
    // has a relative standard error of 1/√(2·23) ≈ 15 %, so a factor-2 band around the mean reported error
    // is decisive; the mean of the 24 estimates has standard error spread/√24, and a sampler whose
    // exploration misses part of the pole space would sit several of those below the reference.
    // Q1S2 is checked for bias only: its estimates have a low tail (a run now and then loses a region of
    // the pole space holding posterior mass), so its spread exceeds the reported error, 2.3x at 300 live
    // points and 2.8x at 100 (docs/method.md, "Status of the pole sampler"); the spread is printed.
    // About 1 min of CPU.
    const Measurement data = reference_file();
    for (const auto& [order, live] : {std::pair{Order(1, 1), 100}, std::pair{Order(1, 2), 300}}) {
      const Estimate reference = importance_log_z(data, order, PriorRanges::table1(), 20000);
      FitSettings settings;
      settings.sampler.live = live;
      settings.sampler_kind = SamplerKind::poles;
      std::vector<double> log_z, err;
      int on_poles = 0;
      for (std::uint64_t seed = 100; seed < 124; ++seed) {
        settings.sampler.seed = seed;
        const ModelResult m = fit_order(data, order, settings);
        on_poles += m.sampler == "poles_analytic_residues" ? 1 : 0;
        log_z.push_back(m.run.log_z);
        err.push_back(m.run.log_z_error);
      }
      const auto [mean, spread, reported] = test::seed_scatter(log_z, err);
      const double n = static_cast<double>(log_z.size());
      MESSAGE(order.name(), ", ", live, " live, 24 seeds: mean ln Z ", mean, ", spread ", spread, ", mean reported error ",
              reported, ", importance sampling ", reference.log_z, " ± ", reference.error, ", ", on_poles,
              " runs on the pole sampler");
      CHECK(on_poles == 24);
      if (order == Order(1, 1)) {
        CHECK(spread <= 2.0 * reported);
        CHECK(spread >= 0.5 * reported);
      }
      CHECK(std::abs(mean - reference.log_z) <= 3.0 * std::hypot(spread / std::sqrt(n), reference.error));
    }
  }
}

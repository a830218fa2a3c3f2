// SPDX-License-Identifier: MIT
// A larger order's best model read as a smaller one (selection/reduced_model.hpp) and the missed-mode check
// it feeds (selection/fit.hpp missed_modes), against least squares solved here from the model's formula.
#include "inference/likelihood.hpp"
#include "inference/residue_evidence.hpp"
#include "inference/synthetic_data.hpp"
#include "selection/fit.hpp"
#include "selection/missed_modes.hpp"
#include "selection/order_marginals.hpp"
#include "selection/reduced_model.hpp"

#include <doctest/doctest.h>

#include <Eigen/QR>

#include <cmath>
#include <complex>
#include <memory>
#include <vector>

namespace {
/// A fit's marginals, built anew for each check below (their models differ from call to call).
admitgen::OrderMarginals& fresh_marginals(const admitgen::Measurement& data, const admitgen::FitSettings& settings) {
  static std::unique_ptr<admitgen::OrderMarginals> marginals;
  marginals = std::make_unique<admitgen::OrderMarginals>(data, settings.data_count, settings.priors.admittance_scale);
  return *marginals;
}
}  // namespace

using namespace admitgen;

namespace {

using cd = std::complex<double>;

// Q1S1 truth: G∞, A, λ, B, C, α, β (s⁻¹).
Eigen::VectorXd truth() {
  Eigen::VectorXd t(7);
  t << 0.5, -20000.0, 8000.0, 2000.0, -200.0, 1500.0, 10000.0;
  return t;
}

// Q2S1 with the truth's poles plus a spurious real pole at 3000 s⁻¹ (first), residues deliberately wrong:
// the reduction must keep poles only.
Eigen::VectorXd larger() {
  Eigen::VectorXd t(9);
  t << 0.1, 5000.0, 3000.0, -1.0, 8000.0, 7.0, 7.0, 1500.0, 10000.0;
  return t;
}

// A run of one sample θ (one live point, its own best), as a sampler of the given name would record it.
ModelResult one_point(const Measurement& data, const FitSettings& settings, const Order& order,
                      const Eigen::VectorXd& theta, const char* sampler) {
  ModelResult m{order, {}, 1, 0.0, {}, {}};
  m.sampler = sampler;
  m.run.dim = order.dim();
  m.run.samples.assign(theta.data(), theta.data() + theta.size());
  m.run.log_likelihood = {Likelihood(data, order, settings.data_count)(theta.data())};
  m.run.log_weight = {0.0};
  m.run.max_log_likelihood = m.run.log_likelihood[0];
  return m;
}

struct LeastSquares {
  Eigen::VectorXd theta;  // Q1S1 packing
  double log_l;
};

// The Q1S1 least-squares residues for real pole λ and pair α + jβ, straight from G = G∞ + A/(λ + jω) +
// Θ/(θ + jω) + Θ*/(θ* + jω) (Θ = B + jC, θ = α + jβ), with A optionally held at `fixed_a` (its column moved to
// the data side), solved by column-pivoting QR: independent of the project's basis and normal equations.
LeastSquares least_squares(const Measurement& data, double lambda, double alpha, double beta, const double* fixed_a) {
  const Eigen::ArrayXd w = data.omega();
  const Eigen::Index n = data.size();
  const bool free_a = fixed_a == nullptr;
  Eigen::MatrixXd a(2 * n, free_a ? 4 : 3);
  Eigen::VectorXd b(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const cd jw(0.0, w[i]), th(alpha, beta);
    std::vector<cd> cols{1.0, 1.0 / (lambda + jw), 1.0 / (th + jw) + 1.0 / (std::conj(th) + jw),
                         cd(0.0, 1.0) / (th + jw) - cd(0.0, 1.0) / (std::conj(th) + jw)};
    cd rhs = data.y[i];
    if (!free_a) {
      rhs -= *fixed_a * cols[1];
      cols.erase(cols.begin() + 1);
    }
    for (std::size_t k = 0; k < cols.size(); ++k) {
      a(i, static_cast<Eigen::Index>(k)) = cols[k].real();
      a(n + i, static_cast<Eigen::Index>(k)) = cols[k].imag();
    }
    b[i] = rhs.real();
    b[n + i] = rhs.imag();
  }
  const Eigen::VectorXd r = a.colPivHouseholderQr().solve(b);
  Eigen::VectorXd theta(7);
  if (free_a) theta << r[0], r[1], lambda, r[2], r[3], alpha, beta;
  else theta << r[0], *fixed_a, lambda, r[1], r[2], alpha, beta;
  return {theta, Likelihood(data, Order(1, 1), DataCount::two_per_point)(theta.data())};
}

}  // namespace

TEST_CASE("reduced model: dropping a surplus real pole gives the least-squares likelihood of the poles kept") {
  const Measurement data = test::synthetic(Order(1, 1), truth(), 150, 100.0, 4000.0, 0.01, 20261127);
  const PriorRanges priors = PriorRanges::table1();
  const Eigen::VectorXd big = larger();
  // The two ways of dropping one of the two real poles; the better is the truth's λ.
  const LeastSquares keep_truth = least_squares(data, 8000.0, 1500.0, 10000.0, nullptr);
  const LeastSquares keep_spurious = least_squares(data, 3000.0, 1500.0, 10000.0, nullptr);
  REQUIRE(keep_truth.log_l > keep_spurious.log_l + 100.0);
  // The residues lie inside Table 1's box, so the box-constrained minimum is the unconstrained one. Both
  // solutions are backward stable: their residuals differ by O(ε cond(A)) ≈ 1e-16 · 1e5 relative, and ln L =
  // −(K/2) ln S (K = 300) is stationary in r at the minimum, so 1e-7 nats bounds the difference with room.
  CHECK(std::abs(keep_truth.theta[1]) < 40000.0);
  const double reduced =
      reduced_log_likelihood(data, Order(1, 1), Order(2, 1), big.data(), priors, DataCount::two_per_point);
  CHECK(std::abs(reduced - keep_truth.log_l) < 1e-7);
  // It can only beat the true θ (least squares minimises S at those poles), by about half a χ²₄.
  const double at_truth = Likelihood(data, Order(1, 1), DataCount::two_per_point)(truth().data());
  CHECK(reduced >= at_truth);
  CHECK(reduced < at_truth + 15.0);
  // small = big: the run's own θ with its residues refitted.
  const Eigen::VectorXd own = truth();
  CHECK(std::abs(reduced_log_likelihood(data, Order(1, 1), Order(1, 1), own.data(), priors, DataCount::two_per_point) -
                 keep_truth.log_l) < 1e-7);
}

TEST_CASE("reduced model: a residue held at its prior bound, the others refitted") {
  const Measurement data = test::synthetic(Order(1, 1), truth(), 150, 100.0, 4000.0, 0.01, 20261128);
  PriorRanges priors = PriorRanges::table1();
  priors.a = {-17000.0, 17000.0};  // the truth's A = −20 000 lies outside: the minimum sits on A = −17 000
  const Eigen::VectorXd big = larger();
  const double a_bound = -17000.0;
  const LeastSquares reference = least_squares(data, 8000.0, 1500.0, 10000.0, &a_bound);
  // S is a convex quadratic whose free minimum has A below the bound, so over the half-space A ≥ −17 000 its
  // minimum lies on A = −17 000 (the reference); the reference's other residues lie inside their boxes, so it
  // is the minimum over the box too.
  REQUIRE(least_squares(data, 8000.0, 1500.0, 10000.0, nullptr).theta[1] < a_bound);
  CHECK(std::abs(reference.theta[0]) < 1.0);
  CHECK(std::abs(reference.theta[3]) < 10000.0);
  CHECK(std::abs(reference.theta[4]) < 1000.0);
  // Tolerance as above; the active-set solver stops at a relative KKT tolerance of 1e-12.
  const double reduced =
      reduced_log_likelihood(data, Order(1, 1), Order(2, 1), big.data(), priors, DataCount::two_per_point);
  CHECK(std::abs(reduced - reference.log_l) < 1e-6);
}

TEST_CASE("missed modes: a smaller order below what the larger order's best shows is flagged for a re-run") {
  const Measurement data = test::synthetic(Order(1, 1), truth(), 150, 100.0, 4000.0, 0.01, 20261127);
  FitSettings settings;
  const auto one_point_run = [&](const Order& order, const Eigen::VectorXd& theta) {
    return one_point(data, settings, order, theta, "full");
  };
  // The Q1S1 run stuck in a poor mode (its real pole at 2000 s⁻¹, residues refitted: its own best).
  Eigen::VectorXd poor = least_squares(data, 2000.0, 1500.0, 10000.0, nullptr).theta;
  // Q2S1 at the truth's least squares plus a spurious pole that carries nothing (A = 0).
  const Eigen::VectorXd ls = least_squares(data, 8000.0, 1500.0, 10000.0, nullptr).theta;
  Eigen::VectorXd big(9);
  big << ls[0], 0.0, 3000.0, ls[1], ls[2], ls[3], ls[4], ls[5], ls[6];
  const std::vector<ModelResult> models{one_point_run(Order(1, 1), poor), one_point_run(Order(2, 1), big)};
  REQUIRE(models[1].run.max_log_likelihood > models[0].run.max_log_likelihood + 100.0);
  // The check by contained orders sees nothing (Q2S1 is the better one); the check by larger orders does.
  CHECK(missed_modes(models).empty());
  const auto missed = missed_modes(data, settings, models, fresh_marginals(data, settings));
  REQUIRE(missed.size() == 1);
  CHECK(missed[0].order == 0);
  CHECK(missed[0].contained == 1);
  CHECK(missed[0].larger);
  CHECK(missed[0].reference_log_l ==
        doctest::Approx(least_squares(data, 8000.0, 1500.0, 10000.0, nullptr).log_l).epsilon(1e-12));
  const auto warnings = missed_mode_warnings(models, missed);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].rfind("Q1S1:", 0) == 0);
  CHECK(warnings[0].find("larger order Q2S1 with its surplus terms dropped; the sampler missed a mode of Q1S1") !=
        std::string::npos);
  // With the Q1S1 run at the truth's poles nothing is missed.
  const std::vector<ModelResult> fine{one_point_run(Order(1, 1), ls), models[1]};
  CHECK(missed_modes(data, settings, fine, fresh_marginals(data, settings)).empty());
}

TEST_CASE("missed modes of the pole sampler: compared on the marginal of the poles, both ways") {
  // Runs of the pole sampler are compared on what it samples, the marginal L(ψ) (inference/residue_evidence.hpp,
  // whose accuracy has its own tests): the logic under test is which poles are dropped or added, and which run
  // is flagged. The reference values are that marginal at the poles the check should have built.
  const Measurement data = test::synthetic(Order(1, 1), truth(), 150, 100.0, 4000.0, 0.01, 20261127);
  FitSettings settings;
  const ResidueEvidence q1s1(data, Order(1, 1), settings.data_count, settings.priors.admittance_scale);
  const ResidueEvidence q2s1(data, Order(2, 1), settings.data_count, settings.priors.admittance_scale);
  const auto one_point_run = [&](const Order& order, const Eigen::VectorXd& theta) {
    return one_point(data, settings, order, theta, kPoleSamplerName);
  };
  Eigen::VectorXd poor = truth();
  poor[2] = 2000.0;  // Q1S1 stuck with its real pole at 2000 s⁻¹
  const std::vector<double> truth_poles{8000.0, 1500.0, 10000.0}, poor_poles{2000.0, 1500.0, 10000.0};
  REQUIRE(q1s1(truth_poles.data()) > q1s1(poor_poles.data()) + 100.0);

  SUBCASE("the smaller run is flagged by the larger run's poles with the spurious one dropped") {
    const std::vector<ModelResult> models{one_point_run(Order(1, 1), poor), one_point_run(Order(2, 1), larger())};
    const auto missed = missed_modes(data, settings, models, fresh_marginals(data, settings));
    REQUIRE(missed.size() == 1);
    CHECK(missed[0].order == 0);
    CHECK(missed[0].contained == 1);
    CHECK(missed[0].larger);
    CHECK(missed[0].marginal);
    CHECK(missed[0].reference_log_l == doctest::Approx(q1s1(truth_poles.data())).epsilon(1e-12));
    CHECK(missed[0].own_log_l == doctest::Approx(q1s1(poor_poles.data())).epsilon(1e-12));
    const auto warnings = missed_mode_warnings(models, missed);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("Q1S1: the peak of ln L(poles)") == 0);
  }
  SUBCASE("the larger run is flagged by the smaller run's poles completed with its surplus pole") {
    Eigen::VectorXd big_poor = larger();
    big_poor[4] = 2000.0;  // its second real pole, the one that should sit at 8000 s⁻¹
    const std::vector<ModelResult> models{one_point_run(Order(1, 1), truth()), one_point_run(Order(2, 1), big_poor)};
    const auto missed = missed_modes(data, settings, models, fresh_marginals(data, settings));
    REQUIRE(missed.size() == 1);
    CHECK(missed[0].order == 1);
    CHECK(missed[0].contained == 0);
    CHECK_FALSE(missed[0].larger);
    // The best completion: the truth's poles plus one of Q2S1's real poles (3000 or 2000 s⁻¹).
    const std::vector<double> with_3000{8000.0, 3000.0, 1500.0, 10000.0}, with_2000{8000.0, 2000.0, 1500.0, 10000.0};
    CHECK(missed[0].reference_log_l ==
          doctest::Approx(std::max(q2s1(with_3000.data()), q2s1(with_2000.data()))).epsilon(1e-12));
  }
  SUBCASE("a larger run at the best completion of the smaller run's peak is not flagged, nor is the smaller") {
    // Q2S1's candidates: Q1S1's poles plus one of larger()'s real poles (3000 or 8000 s⁻¹: a doubled pole
    // doubles the prior variance of its residue, which can pay). The run sits at the better one.
    const std::vector<double> with_3000{8000.0, 3000.0, 1500.0, 10000.0}, with_8000{8000.0, 8000.0, 1500.0, 10000.0};
    Eigen::VectorXd big = larger();
    big[4] = 8000.0;
    big[2] = q2s1(with_3000.data()) > q2s1(with_8000.data()) ? 3000.0 : 8000.0;
    const std::vector<ModelResult> models{one_point_run(Order(1, 1), truth()), one_point_run(Order(2, 1), big)};
    CHECK(missed_modes(data, settings, models, fresh_marginals(data, settings)).empty());
  }
}

// SPDX-License-Identifier: MIT
// Warnings for posteriors against a bound of the prior range (selection/prior_edge.hpp), on hand-made
// summaries: each rule of the header decided on both sides of its threshold.
#include "selection/prior_edge.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace admitgen;

namespace {

/// Q1S1 (θ: G∞, A, λ, B, C, α, β) with every posterior in the middle of Table 1's ranges, std 1 % of width.
ModelResult model() {
  ModelResult m{Order(1, 1), {}, 100, 0.0, {}};
  const PriorRanges pr = PriorRanges::table1();
  const auto names = m.order.parameter_names();
  const auto families = m.order.families();
  for (std::size_t k = 0; k < names.size(); ++k) {
    const Range& r = pr.of(families[k]);
    const double mid = 0.5 * (r.lo + r.hi) + 0.1 * r.width(), sd = 0.01 * r.width();
    m.parameters.push_back({names[k], mid, sd, mid - 2 * sd, mid + 2 * sd, mid});
  }
  return m;
}

void place(ParameterSummary& p, double lo, double hi, double sd) {
  p.ci95_lo = lo, p.ci95_hi = hi, p.std = sd, p.mean = 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("prior edge: a concentrated posterior within 1 % of a cut bound is reported, nothing else") {
  const PriorRanges pr = PriorRanges::table1();
  CHECK_FALSE(prior_edge_warning(model(), pr));

  SUBCASE("G_inf against -1 (width 2: reach 0.02, concentration 0.1)") {
    ModelResult m = model();
    place(m.parameters[0], -0.9999, -0.985, 0.004);
    const auto w = prior_edge_warning(m, pr);
    REQUIRE(w);
    CHECK(w->find("G_inf at -1 ") != std::string::npos);
    place(m.parameters[0], -0.979, -0.95, 0.004);  // 0.021 from the bound: outside the reach
    CHECK_FALSE(prior_edge_warning(m, pr));
    place(m.parameters[0], -0.9999, -0.5, 0.11);  // reaches the bound but spread: unconstrained, not cut
    CHECK_FALSE(prior_edge_warning(m, pr));
  }
  SUBCASE("C against its upper bound 1000") {
    ModelResult m = model();
    place(m.parameters[4], 992.0, 999.9, 2.4);
    CHECK(prior_edge_warning(m, pr));
    place(m.parameters[0], 0.985, 0.9999, 0.004);  // two parameters: one warning naming both
    const auto w = prior_edge_warning(m, pr);
    REQUIRE(w);
    CHECK(w->find("C_1 at 1000 ") != std::string::npos);
    CHECK(w->find("G_inf at 1 ") != std::string::npos);
  }
  SUBCASE("lambda and alpha at 0 are causality limits, lambda at its upper bound is a cut") {
    ModelResult m = model();
    place(m.parameters[2], 0.5, 30.0, 8.0);
    place(m.parameters[5], 0.1, 20.0, 5.0);
    CHECK_FALSE(prior_edge_warning(m, pr));
    place(m.parameters[2], 74500.0, 74999.0, 120.0);
    CHECK(prior_edge_warning(m, pr));
    PriorRanges band = pr;
    band.lambda.lo = 600.0;  // a band prior's lower bound above 0 is a cut
    place(m.parameters[2], 600.5, 900.0, 80.0);
    CHECK(prior_edge_warning(m, band));
  }
}

TEST_CASE("prior edge: residues in the Gaussian prior's tail, with advice that follows the data's passive bound") {
  PriorRanges pr = PriorRanges::table1();
  pr.residues = ResiduePrior::gaussian;
  pr.admittance_scale = 1.0;  // G∞'s prior standard deviation is the scale itself
  ModelResult m = model();
  place(m.parameters[0], -0.5, 0.5, 0.2);  // G∞ = 0: within 4 prior standard deviations
  CHECK_FALSE(prior_edge_warning(m, pr));
  place(m.parameters[0], -9.7, -9.3, 0.1);  // G∞ = -9.5: 9.5 standard deviations out, as rect_10cm's Q4S4
  const auto plain = prior_edge_warning(m, pr);
  REQUIRE(plain);
  CHECK(plain->find("G_inf = -9.5 (9.5 prior standard deviations)") != std::string::npos);
  CHECK(plain->find("if such values are physical, raise it") != std::string::npos);

  SUBCASE("the passive estimate sits at the passive bound: the tail buys Re G < 0, not physics") {
    m.passive.best_sample_relative_rms_residual = 0.0475;
    m.passive.relative_rms_residual = 0.221;
    m.passive.passive_bound_relative_rms_residual = 0.210;  // 1.05x: within 1.25x of the bound
    const auto w = prior_edge_warning(m, pr);
    REQUIRE(w);
    CHECK(w->find("they are not physical") != std::string::npos);
    CHECK(w->find("21 % (the passive bound) where the best sample reaches 4.75 %") != std::string::npos);
    CHECK(w->find("raise it") == std::string::npos);
  }
  SUBCASE("a larger order would fit better passively (estimate above 1.25x the bound): the plain advice stays") {
    m.passive.best_sample_relative_rms_residual = 0.0475;
    m.passive.relative_rms_residual = 0.30;
    m.passive.passive_bound_relative_rms_residual = 0.21;  // 1.43x
    const auto w = prior_edge_warning(m, pr);
    REQUIRE(w);
    CHECK(w->find("if such values are physical, raise it") != std::string::npos);
  }
}

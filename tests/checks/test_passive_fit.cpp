// SPDX-License-Identifier: MIT
// --passive: the prior truncated to passive models (selection/fit.cpp, inference/nested_sampler.cpp).
#include "data/csv_reader.hpp"
#include "inference/nested_sampler.hpp"
#include "model/passivity.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace admitgen;

TEST_CASE("nested sampling of a prior truncated by ln L = -inf: evidence of the renormalised prior") {
  // Prior U(-1, 1)^2, L = N(0, 0.1^2 I), support x > 0 (half of the prior, half of the likelihood mass).
  // Renormalised prior density 1/2 on the support: Z = ∫_{x>0} L (1/2) = 1/4 (erf(7.07) = 1 to 1e-22);
  // support fraction 1/2, estimated from n / draws (binomial: std of ln f = sqrt((1 - f)/n) = 0.045).
  constexpr double kSigma = 0.1;
  NestedSettings s;
  s.live = 250;
  s.seed = 7;
  const auto run = run_nested_sampling(
      2, [](const double* u, double* th) { th[0] = 2 * u[0] - 1, th[1] = 2 * u[1] - 1; },
      [](const double* th) {
        if (th[0] <= 0.0) return -std::numeric_limits<double>::infinity();
        return -0.5 * (th[0] * th[0] + th[1] * th[1]) / (kSigma * kSigma) - std::log(2 * 3.14159265358979 * kSigma * kSigma);
      },
      s);
  CHECK(std::abs(run.log_z - std::log(0.25)) <= 3.0 * run.log_z_error);
  CHECK(std::abs(run.log_support_fraction - std::log(0.5)) <= 3.0 * std::sqrt(0.5 / s.live));
  CHECK(std::isfinite(run.information));
  for (double l : run.log_likelihood) CHECK(std::isfinite(l));  // no point outside the support is ever kept
}

TEST_CASE("fit --passive: every posterior sample is passive, evidence under the truncated prior") {
  // Q1S1 on the reference data (its generating model is passive): with live 60 the run takes ~1 s.
  const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
  FitSettings settings;
  settings.sampler.live = 60;
  settings.sampler.seed = 3;
  settings.sampler.dlogz = 0.5;
  settings.passive = true;
  const Order order(1, 1);
  const ModelResult m = fit_order(data, order, settings);
  CHECK(m.run.log_support_fraction < 0.0);                         // part of the Table-1 prior is non-passive
  CHECK(m.run.log_support_fraction > std::log(1.0 / 10000.0));
  std::size_t checked = 0;
  for (std::size_t i = 0; i < m.run.size(); ++i) {
    CHECK(is_passive(order, m.run.point(i)));
    ++checked;
  }
  CHECK(checked == m.run.size());
  CHECK(std::isfinite(m.run.log_z));
}

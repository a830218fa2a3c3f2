// SPDX-License-Identifier: MIT
// Evidence by quadrature (inference/quadrature_evidence.hpp) against closed forms: Gaussian likelihoods
// in u whose integral over [0, 1] is an erf expression, narrow (1e-7 of the prior) and broad, inside and
// on the prior's edge, two modes of different widths, and a log-uniform prior. The target is a relative
// error of 1e-6 in Z, so ln Z must agree to 2e-6 nats (the Gauss-Kronrod estimate is pessimistic; 2x
// for the rounding of the reference); the reported error must cover the true one. Posterior mean and
// standard deviation are integrals of the same nodes, exact to 1e-6 of the standard deviation.
#include "inference/evidence.hpp"
#include "inference/posterior.hpp"
#include "inference/quadrature_evidence.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

/// ln ∫₀¹ Σ_m w_m e^{−(u−μ_m)²/(2s_m²)} du in closed form.
double exact_log_z(const std::vector<std::array<double, 3>>& modes) {
  double z = 0.0;
  for (const auto& [w, mu, s] : modes)
    z += w * s * std::sqrt(EIGEN_PI / 2.0) * (std::erf((1.0 - mu) / (s * std::sqrt(2.0))) + std::erf(mu / (s * std::sqrt(2.0))));
  return std::log(z);
}

/// ln L summed in log space, so ln L stays smooth (quadratic near each mode) where L underflows.
Model mixture(const std::vector<std::array<double, 3>>& modes) {
  return Model{{"x"}, [](const double* u, double* th) { th[0] = u[0]; },
               [modes](const double* th) {
                 double log_l = -std::numeric_limits<double>::infinity();
                 for (const auto& [w, mu, s] : modes)
                   log_l = log_add_exp(log_l, std::log(w) - 0.5 * (th[0] - mu) * (th[0] - mu) / (s * s));
                 return log_l;
               }};
}

}  // namespace

TEST_CASE("quadrature evidence: Gaussian peaks of width 1e-7 to 0.2, inside, on the edge, two modes") {
  const std::vector<std::vector<std::array<double, 3>>> cases{
      {{1.0, 0.3, 1e-7}},                      // narrow, inside
      {{1.0, 0.61803, 2e-3}},                  // moderate
      {{1.0, 0.0, 1e-4}},                      // on the lower edge: half the Gaussian
      {{1.0, 1.0, 0.2}},                       // broad, on the upper edge
      {{1.0, 0.2, 1e-4}, {3.0, 0.7, 1e-2}},    // two modes, the broad one dominant (the narrow 0.3 %)
      {{1.0, 0.2, 1e-3}, {1e-3, 0.9, 1e-2}}};  // a narrow dominant mode and a small broad one
  for (const auto& modes : cases) {
    const NestedRun run = evidence_by_quadrature(mixture(modes));
    const double exact = exact_log_z(modes);
    INFO("first mode at ", modes[0][1], " width ", modes[0][2], ": ln Z ", run.log_z, " exact ", exact, " calls ",
         run.calls, " reported error ", run.log_z_error);
    CHECK(std::abs(run.log_z - exact) <= 2e-6);
    CHECK(std::abs(run.log_z - exact) <= std::max(run.log_z_error, 1e-12) + 1e-12);
    CHECK(run.calls < 5000);
    CHECK(run.stopped_by == "quadrature");
  }
}

TEST_CASE("quadrature evidence: posterior moments, maximum and a log-uniform prior") {
  // One Gaussian of mean 0.4 and std 1e-3 in θ = u: mean 0.4 and std 1e-3 (mass outside [0, 1]: 0).
  const double mu = 0.4, s = 1e-3;
  const NestedRun run = evidence_by_quadrature(mixture({{1.0, mu, s}}));
  const auto summary = summarize(run, {"x"});
  CHECK(summary[0].mean == doctest::Approx(mu).epsilon(1e-6 * s / mu));
  CHECK(summary[0].std == doctest::Approx(s).epsilon(1e-6));
  CHECK(summary[0].max_likelihood == doctest::Approx(mu).epsilon(1e-9));
  // The 95 % interval from the weighted nodes: μ ± 1.95996 s to 1 % of s (nodes interpolated linearly).
  CHECK(std::abs(summary[0].ci95_lo - (mu - 1.959964 * s)) < 0.01 * s);
  CHECK(std::abs(summary[0].ci95_hi - (mu + 1.959964 * s)) < 0.01 * s);

  // Log-uniform θ on [1, 100] (θ = 100^u), L = e^{−(ln θ − ln 10)²/(2·0.01²)}: in u the same Gaussian
  // with mean ½ and std 0.01/ln 100, so Z = 0.01/ln 100 · √(2π).
  const Model log_uniform{{"theta"}, [](const double* u, double* th) { th[0] = std::pow(100.0, u[0]); },
                          [](const double* th) {
                            const double d = std::log(th[0]) - std::log(10.0);
                            return -0.5 * d * d / 1e-4;
                          }};
  const NestedRun lr = evidence_by_quadrature(log_uniform);
  CHECK(std::abs(lr.log_z - std::log(0.01 / std::log(100.0) * std::sqrt(2.0 * EIGEN_PI))) <= 2e-6);
}

TEST_CASE("quadrature evidence: no parameter is the likelihood itself") {
  const Model none{{}, [](const double*, double*) {}, [](const double*) { return -3.5; }};
  const NestedRun run = evidence_by_quadrature(none);
  CHECK(run.log_z == -3.5);
  CHECK(run.log_z_error == 0.0);
  CHECK(run.calls == 1);
}

// SPDX-License-Identifier: MIT
// The pole sampler (residues integrated analytically, inference/poles_sampler.hpp) against the full
// sampler, in the doctest suite "statistical" (sampler runs). Tolerance: 3 combined standard errors
// √(e_poles² + e_full²), a 99.7 % band for two independent estimates. Sizes: 300 live points, seed 1
// (each order ~1-3 s per sampler on two cores).
#include "data/csv_reader.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace admitgen;

namespace {

void check_agreement(const Measurement& data, const Order& order, FitSettings settings) {
  settings.sampler_kind = SamplerKind::full;
  const ModelResult full = fit_order(data, order, settings);
  settings.sampler_kind = SamplerKind::poles;
  const ModelResult poles = fit_order(data, order, settings);
  const double tol = 3.0 * std::hypot(poles.run.log_z_error, full.run.log_z_error);
  MESSAGE(order.name(), ": poles ", poles.run.log_z, " ± ", poles.run.log_z_error, " (", poles.run.calls,
          " calls, box correction ", poles.truncation_correction, " ± ", poles.truncation_correction_error,
          "), full ", full.run.log_z, " ± ", full.run.log_z_error, " (", full.run.calls, " calls)");
  CHECK(poles.sampler == "poles_analytic_residues");
  CHECK(std::abs(poles.run.log_z - full.run.log_z) <= tol);
  // The complete posterior: the residues' posterior means agree too (within 3 combined posterior
  // standard errors of a mean, σ/√ESS with ESS ≥ 100 for these runs: 0.3 σ is generous).
  for (std::size_t k = 0; k < full.parameters.size(); ++k) {
    const ParameterSummary &a = poles.parameters[k], &b = full.parameters[k];
    INFO(a.name, ": poles ", a.mean, " ± ", a.std, ", full ", b.mean, " ± ", b.std);
    CHECK(std::abs(a.mean - b.mean) <= 0.5 * std::max(a.std, b.std) + 1e-12);
  }
}

Measurement reference() { return read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{}); }

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("pole sampler: ln Z agrees with the full sampler on the reference file (Q0S0, Q0S1, Q1S1)") {
    FitSettings settings;
    settings.sampler.live = 300;
    const Measurement data = reference();
    for (const Order& o : {Order(0, 0), Order(0, 1), Order(1, 1)}) check_agreement(data, o, settings);
  }

}

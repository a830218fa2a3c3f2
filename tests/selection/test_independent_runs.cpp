// SPDX-License-Identifier: MIT
// An order's first run made of independent runs (FitSettings::runs): the live points split, the same merged run
// from fit_order (a library unit) and from a fit's first round, one run where the evidence is analytic, and the
// settings that leave a run too few live points refused.
#include "core/errors.hpp"
#include "core/progress.hpp"
#include "data/csv_reader.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace admitgen;

TEST_CASE("independent runs: fit_order and a fit's first round merge the same runs, and Q0S0 stays analytic") {
  const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
  FitSettings settings;
  settings.qmax = settings.smax = 1;
  settings.sampler.live = 41;  // split 21 + 20
  settings.runs = 2;
  settings.threads = 2;
  Progress quiet(false);
  const std::vector<ModelResult> first = run_first_round(data, settings, quiet);
  REQUIRE(first.size() == 4);  // Q0S0, Q0S1, Q1S0, Q1S1
  CHECK(first[0].run.stopped_by == "analytic");
  for (const ModelResult& m : first) CHECK(m.live == 41);
  const ModelResult alone = fit_order(data, Order(1, 1), settings);
  CHECK(alone.run.log_z == first[3].run.log_z);  // bitwise: the same parts, merged in the same order
  CHECK(alone.run.log_z_error == first[3].run.log_z_error);
  CHECK(alone.run.samples == first[3].run.samples);
  // The error is never below √(H/n) of the 41 live points (the runs' scatter only raises it).
  CHECK(alone.run.log_z_error >= std::sqrt(alone.run.information / 41.0) * (1.0 - 1e-12));
  settings.runs = 1;
  const ModelResult one = fit_order(data, Order(1, 1), settings);
  CHECK(one.live == 41);
  CHECK(one.run.log_z != alone.run.log_z);
}

TEST_CASE("independent runs: fewer than 5 live points per run are refused, naming both settings") {
  const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
  FitSettings settings;
  settings.sampler.live = 19;
  settings.runs = 4;  // 19 / 4 = 4 per run
  try {
    (void)fit_order(data, Order(1, 1), settings);
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    CHECK(e.settings() == std::vector<std::string>{"sampler.live", "runs", "runs", "sampler.live"});
  }
}

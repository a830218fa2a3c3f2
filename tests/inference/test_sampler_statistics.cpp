// SPDX-License-Identifier: MIT
// Sampler statistics (docs/validation.md), in the doctest suite "statistical" (many sampler runs;
// left out of the sanitizer job). Sizes and seeds are chosen so each case is decisive and takes a
// few seconds.
#include "data/csv_reader.hpp"
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/priors.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numeric>

using namespace admitgen;

namespace {

NestedRun sample(const Measurement& data, const Order& o, bool reduced, int live, std::uint64_t seed) {
  const PriorTransform t(o, PriorRanges::table1(), reduced);
  const Likelihood like(data, o, DataCount::two_per_point);
  NestedSettings s;
  s.live = live;
  s.seed = seed;
  const Model model{o.parameter_names(), [&](const double* u, double* th) { t(u, th); },
                    [&](const double* th) { return like(th); }, [&](double* u) { t.fold(u); }};
  return run_nested_sampling(model, s);
}

Measurement reference() { return read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{}); }

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("error honesty: seed-to-seed spread of ln Z matches the mean reported error within 2x") {
    // Q1S1 (7-D) on the reference file with 100 live points and 24 seeds: the reported error √(H/n) is
    // ≈ 0.6 nats. The sample standard deviation of 24 values has a relative standard error of
    // 1/√(2·23) ≈ 15 %, so a factor-2 band is decisive (a sampler whose chains do not decorrelate shows
    // a spread several times the reported error, see reference/README.md for dynesty's Q2S1).
    const Measurement data = reference();
    const Order o(1, 1);
    std::vector<double> log_z, err;
    for (std::uint64_t seed = 100; seed < 124; ++seed) {
      const NestedRun run = sample(data, o, true, 100, seed);
      log_z.push_back(run.log_z);
      err.push_back(run.log_z_error);
    }
    const auto [mean, spread, reported] = test::seed_scatter(log_z, err);
    MESSAGE("Q1S1, 100 live, 24 seeds: mean ln Z ", mean, ", spread ", spread, ", mean reported error ", reported);
    CHECK(spread <= 2.0 * reported);
    CHECK(spread >= 0.5 * reported);
  }

  TEST_CASE("symmetry reduction leaves ln Z unchanged: Q0S1 and Q2S0, reduced vs full prior") {
    // Tolerance: 3 combined standard errors √(e_r² + e_f²), a 99.7 % band for two independent runs.
    const Measurement data = reference();
    for (const Order& o : {Order(0, 1), Order(2, 0)}) {
      const NestedRun reduced = sample(data, o, true, 300, 7);
      const NestedRun full = sample(data, o, false, 300, 8);
      const double tol = 3.0 * std::hypot(reduced.log_z_error, full.log_z_error);
      MESSAGE(o.name(), ": reduced ", reduced.log_z, " ± ", reduced.log_z_error, ", full ", full.log_z, " ± ",
              full.log_z_error);
      CHECK(std::abs(reduced.log_z - full.log_z) <= tol);
    }
  }
}

// SPDX-License-Identifier: MIT
// Independent runs merged into one (inference/merged_runs.hpp; docs/method.md, "Missed modes").
#include "inference/evidence.hpp"
#include "inference/merged_runs.hpp"
#include "inference/nested_sampler.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace admitgen;

namespace {

// A Gaussian bump of width w at the centre of the unit square, under the uniform prior: Z = ∫ L du =
// 2π w² to within the bump's mass outside the square (e^{−0.5²/(2w²)} ≈ 1e-54 at w = 0.05, nothing).
constexpr double kWidth = 0.05;
Model bump() {
  return Model{{"x", "y"}, [](const double* u, double* th) { th[0] = u[0], th[1] = u[1]; },
               [](const double* th) {
                 const double dx = th[0] - 0.5, dy = th[1] - 0.5;
                 return -(dx * dx + dy * dy) / (2.0 * kWidth * kWidth);
               }};
}

NestedRun run(int live, std::uint64_t seed) {
  NestedSettings s;
  s.live = live;
  s.seed = seed;
  return run_nested_sampling(bump(), s);
}

double posterior_mass(const NestedRun& r) {
  double sum = 0.0;
  for (double w : r.log_weight) sum += std::exp(w - r.log_z);
  return sum;
}

}  // namespace

TEST_CASE("merged runs: k copies of one run keep its ln Z and divide its error by sqrt(k)") {
  // Closed form: the mean of k equal evidences is that evidence; √(Σ (1/k)² δ²) = δ/√k. Every row kept,
  // the weights divided by k, so the posterior still sums to 1 (to rounding, 1e-12).
  const NestedRun one = run(50, 3);
  const NestedRun merged = merge_runs({one, one, one, one}, 50);
  CHECK(merged.log_z == doctest::Approx(one.log_z).epsilon(1e-14));
  CHECK(merged.log_z_error == doctest::Approx(one.log_z_error / 2.0).epsilon(1e-12));
  CHECK(merged.size() == 4 * one.size());
  CHECK(merged.calls == 4 * one.calls);
  CHECK(std::abs(posterior_mass(merged) - 1.0) < 1e-12);
  CHECK(merge_runs({one}, 50).log_likelihood == one.log_likelihood);
}

TEST_CASE("merged runs: the last k·live rows are where the runs ended, each part in ascending ln L") {
  const std::vector<NestedRun> runs{run(40, 11), run(40, 12)};
  const NestedRun merged = merge_runs(runs, 40);
  std::vector<double> ends, merged_ends;
  for (const NestedRun& r : runs) ends.insert(ends.end(), r.log_likelihood.end() - 40, r.log_likelihood.end());
  std::sort(ends.begin(), ends.end());
  merged_ends.assign(merged.log_likelihood.end() - 80, merged.log_likelihood.end());
  CHECK(merged_ends == ends);
  CHECK(std::is_sorted(merged.log_likelihood.begin(), merged.log_likelihood.end() - 80));
}

TEST_SUITE("statistical") {
  TEST_CASE("merged runs: four runs of 100 live points find Z of a Gaussian bump within 3 merged errors") {
    // Truth ln(2π w²) = −4.1605. Four runs of 100 live points on seeds 21-24, merged: the merged error (about
    // √(H/400) ≈ 0.08 nats at H ≈ 2.5) bounds the miss at 3 errors (a 0.3 % chance for an honest error). Its
    // error is about half of one run's, as for one run of 400 live points.
    const double truth = std::log(2.0 * M_PI * kWidth * kWidth);
    std::vector<NestedRun> runs;
    for (std::uint64_t seed = 21; seed <= 24; ++seed) runs.push_back(run(100, seed));
    const NestedRun merged = merge_runs(runs, 100);
    CAPTURE(merged.log_z);
    CAPTURE(merged.log_z_error);
    CHECK(std::abs(merged.log_z - truth) < 3.0 * merged.log_z_error);
    CHECK(merged.log_z_error < 0.6 * runs.front().log_z_error);
    CHECK(std::abs(posterior_mass(merged) - 1.0) < 1e-12);
  }
}

// SPDX-License-Identifier: MIT
// Merged runs (inference/run_merge.hpp): the live counts of hand-built runs against the thread count written
// out by hand, and two runs of a Gaussian likelihood merged against its closed-form evidence.
#include "inference/nested_sampler.hpp"
#include "inference/run_merge.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace admitgen;

namespace {

/// A one-dimensional run whose points are `deaths` and then `final_live` (ascending), each θ equal to its
/// ln L, with finite weights (their values do not enter the merge).
NestedRun hand_run(const std::vector<double>& deaths, const std::vector<double>& final_live) {
  NestedRun run;
  run.dim = 1;
  run.iterations = static_cast<long>(deaths.size());
  for (const auto* part : {&deaths, &final_live})
    for (double l : *part) {
      run.samples.push_back(l);
      run.log_likelihood.push_back(l);
      run.log_weight.push_back(0.0);
    }
  return run;
}

}  // namespace

TEST_CASE("merged runs: the live count at each point is the number of threads alive there") {
  // Run 1 (2 live points): deaths at ln L 1 and 3, final live points 5 and 6. Run 2 (1 live point): death at
  // 2, final live point 4. Together: 3 threads up to 4 (the deaths 1, 2, 3 and run 2's last point), then run
  // 1's two threads close one at a time: counts 3, 3, 3, 3, 2, 1, as one run of 3 live points whose final
  // live points are 4, 5 and 6.
  const NestedRun one = hand_run({1.0, 3.0}, {5.0, 6.0}), two = hand_run({2.0}, {4.0});
  const NestedRun merged = merge_runs({{&one, 2}, {&two, 1}});
  REQUIRE(merged.size() == 6);
  const std::vector<int> counts{3, 3, 3, 3, 2, 1};
  double log_x = 0.0, z = 0.0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    CHECK(merged.point(i)[0] == static_cast<double>(i + 1));  // sorted by ln L
    const double shrink = -1.0 / counts[i];
    // w_i = L_i (X_{i−1} − X_i), X_i = X_{i−1} e^{−1/n_i}; rounding only (a few ulps of values near 1).
    const double log_w = static_cast<double>(i + 1) + log_x + std::log(1.0 - std::exp(shrink));
    CHECK(merged.log_weight[i] == doctest::Approx(log_w).epsilon(1e-14));
    z += std::exp(log_w);
    log_x += shrink;
  }
  CHECK(merged.log_z == doctest::Approx(std::log(z)).epsilon(1e-14));
  CHECK(merged.iterations == 3);
}

TEST_CASE("merged runs: two runs of a Gaussian likelihood merge to its closed-form evidence") {
  // L(x) = exp(−|x − c|²/(2 s²)) on the unit square, c = (0.5, 0.5), s = 0.04: Z = 2π s² (the mass outside
  // the square, beyond 12.5 s, is below 1e-30). Two runs of 150 live points on seeds 1 and 2 merged hold
  // 300; the merged ln Z must lie within 4 of its errors √(H/300) (a normal deviate beyond 4 has probability
  // 6e-5: decisive, and the seeds are fixed), and its error must be that of 300 live points, √(150/300) of
  // either run's.
  constexpr double s = 0.04;
  const Model model{{"x", "y"}, [](const double* u, double* th) { th[0] = u[0], th[1] = u[1]; },
                    [](const double* th) {
                      const double dx = th[0] - 0.5, dy = th[1] - 0.5;
                      return -(dx * dx + dy * dy) / (2.0 * s * s);
                    }};
  NestedSettings settings;
  settings.live = 150;
  settings.seed = 1;
  const NestedRun a = run_nested_sampling(model, settings);
  settings.seed = 2;
  const NestedRun b = run_nested_sampling(model, settings);
  const NestedRun merged = merge_runs({{&a, 150}, {&b, 150}});
  const double truth = std::log(2.0 * M_PI * s * s);
  CHECK(std::abs(merged.log_z - truth) < 4.0 * merged.log_z_error);
  CHECK(merged.log_z_error == doctest::Approx(a.log_z_error * std::sqrt(0.5)).epsilon(0.1));
  CHECK(merged.size() == a.size() + b.size());
  CHECK(merged.calls == a.calls + b.calls);
}

TEST_CASE("merged runs: the scatter error of runs whose ln Z disagree") {
  // Parts with ln Z 10, 12, 17 and 2, 1, 1 live points: μ = 49/4, Σ n_k (ln Z_k − μ)² = 2·2.25² + 0.25² + 4.75²
  // = 32.75 over m − 1 = 2 gives ĉ = 16.375, and the error √(ĉ/4). Equal ln Z scatter by 0; one run has no
  // scatter to measure. Exact up to rounding.
  NestedRun one = hand_run({1.0, 3.0}, {5.0, 6.0}), two = hand_run({2.0}, {4.0}), three = hand_run({2.5}, {4.5});
  one.log_z = 10.0, two.log_z = 12.0, three.log_z = 17.0;
  CHECK(scatter_error({{&one, 2}, {&two, 1}, {&three, 1}}) == doctest::Approx(std::sqrt(16.375 / 4.0)).epsilon(1e-14));
  two.log_z = three.log_z = 10.0;
  CHECK(scatter_error({{&one, 2}, {&two, 1}, {&three, 1}}) == 0.0);
  CHECK(scatter_error({{&one, 2}}) == 0.0);
}

// SPDX-License-Identifier: MIT
// A re-run of round r is 2^r runs of the live points merged (selection/fit.hpp fit_order; inference/merged_runs.hpp;
// docs/method.md, "Missed modes"): checked here against the same runs made and merged by hand, bit for bit.
#include "core/rng.hpp"
#include "data/csv_reader.hpp"
#include "inference/merged_runs.hpp"
#include "inference/poles_sampler.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

using namespace admitgen;

TEST_CASE("re-run parts: round 1 of an order is its two part runs merged, on the seed streams of the round") {
  const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
  FitSettings given;
  given.sampler.live = 40;
  const FitSettings settings = with_band_priors(given, data);
  const Order order(1, 1);
  const ModelResult rerun = fit_order(data, order, given, {}, 1);
  // The parts by hand: part 0 on the round's stream, part 1 on a stream derived from it.
  NestedSettings part = settings.sampler;
  part.seed = derive_seed(order_seed(settings.sampler.seed, order), 1);
  const std::uint64_t draw_seed = derive_seed(part.seed, 0x7e51dULL);
  std::vector<NestedRun> runs;
  runs.push_back(sample_poles(data, order, settings.priors, settings.reduce_symmetry, settings.data_count, part));
  part.seed = derive_seed(part.seed, 1);
  runs.push_back(sample_poles(data, order, settings.priors, settings.reduce_symmetry, settings.data_count, part));
  const NestedRun merged = complete_residues(data, order, settings.priors, settings.data_count,
                                             merge_runs(runs, settings.sampler.live), draw_seed);
  CHECK(rerun.live == 2 * given.sampler.live);
  CHECK(rerun.run.log_z == merged.log_z);
  CHECK(rerun.run.log_z_error == merged.log_z_error);
  CHECK(rerun.run.calls == runs[0].calls + runs[1].calls);
  CHECK(rerun.run.log_weight == merged.log_weight);
  // Round 0 is one run, as it always was: the same bits as the pole sampler called directly.
  part.seed = derive_seed(order_seed(settings.sampler.seed, order), 0);
  const NestedRun single = run_poles_sampler(data, order, settings.priors, settings.reduce_symmetry,
                                             settings.data_count, part, derive_seed(part.seed, 0x7e51dULL));
  CHECK(fit_order(data, order, given).run.log_z == single.log_z);
}

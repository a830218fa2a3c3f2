// SPDX-License-Identifier: MIT
#include "selection/fit_cost.hpp"

#include "core/errors.hpp"
#include "inference/pole_space.hpp"
#include "inference/residue_evidence.hpp"
#include "selection/grid_growth.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace admitgen {
namespace {

/// Evaluations per order / (live × dim × slices), from the bundled fits (fit_cost.hpp): the full sampler over
/// θ, and the pole sampler over ψ (dim = Q + 2S).
constexpr double kEvaluationsPerLiveDimSlice = 27.0;
constexpr double kPoleEvaluationsPerLiveDimSlice = 15.0;

/// θ in the middle of every prior range (a valid point of any order: λ, α > 0).
std::vector<double> prior_centre(const Order& order, const PriorRanges& priors) {
  std::vector<double> theta;
  for (const Family f : order.families()) theta.push_back(0.5 * (priors.of(f).lo + priors.of(f).hi));
  return theta;
}

double seconds_per_evaluation(const Measurement& data, const Order& order, const FitSettings& settings) {
  const auto theta = prior_centre(order, settings.priors);
  std::function<double()> call;
  if (order_sampler(settings) == SamplerKind::poles) {
    auto evidence = std::make_shared<ResidueEvidence>(data, order, settings.data_count, settings.priors.admittance_scale);
    auto poles = std::make_shared<std::vector<double>>();
    for (int i : pole_indices(order)) poles->push_back(theta[static_cast<std::size_t>(i)]);
    call = [evidence, poles] { return (*evidence)(poles->data()); };
  } else {
    auto likelihood = std::make_shared<Likelihood>(data, order, settings.data_count);
    call = [likelihood, theta] { return (*likelihood)(theta.data()); };
  }
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  double elapsed = 0.0;
  volatile double sink = 0.0;  // keeps the calls
  long calls = 0;
  while (calls < 3 || (elapsed < 0.02 && calls < 100000)) {
    sink += call();
    ++calls;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  return elapsed / static_cast<double>(calls);
}

std::string duration(double seconds) {
  if (seconds < 100.0) return fmt::format("{:.2g} s", seconds);
  if (seconds < 120.0) return fmt::format("{:.0f} s", seconds);
  if (seconds < 7200.0) return fmt::format("{:.2g} min", seconds / 60.0);
  if (seconds < 2.0 * 86400.0) return fmt::format("{:.2g} h", seconds / 3600.0);
  return fmt::format("{:.2g} days", seconds / 86400.0);
}

}  // namespace

double expected_evaluations(const Order& order, const FitSettings& settings, int live) {
  const bool poles = order_sampler(settings) == SamplerKind::poles;
  const double dim = poles ? pole_count(order) : order.dim();
  const double slices = settings.sampler.slices_per_replacement(static_cast<int>(dim));
  return (poles ? kPoleEvaluationsPerLiveDimSlice : kEvaluationsPerLiveDimSlice) * live * dim * slices;
}

double expected_work(const Order& order, const FitSettings& settings, int live) {
  return (1.0 + order.q() + order.s()) * expected_evaluations(order, settings, live);
}

FitCostEstimate estimate_fit_cost(const Measurement& data, const FitSettings& settings) {
  FitCostEstimate e;
  e.points = static_cast<long>(data.size());
  const Order largest(settings.qmax, settings.smax);
  e.seconds_per_evaluation = seconds_per_evaluation(data, largest, settings);
  const double largest_terms = 1.0 + settings.qmax + settings.smax;
  for (int q = 0; q <= settings.qmax; ++q)
    for (int s = 0; s <= settings.smax; ++s) {
      const Order order(q, s);
      e.evaluations += expected_evaluations(order, settings, settings.sampler.live);
      const double seconds = expected_work(order, settings, settings.sampler.live) * e.seconds_per_evaluation / largest_terms;
      e.cpu_seconds += seconds;
      e.longest_order_seconds = std::max(e.longest_order_seconds, seconds);
      ++e.orders;
    }
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  e.threads = std::min(settings.threads > 0 ? settings.threads : cores, e.orders);
  e.wall_seconds = std::max(e.cpu_seconds / e.threads, e.longest_order_seconds);
  // Growth's budget (selection/grid_growth.hpp): the first round's pole passes or kMinGrowthBudgetPasses,
  // whichever is larger; the passes are priced at this data's measured cost per pass.
  if (settings.grid_growth > 0) {
    const double seconds_per_pass = e.seconds_per_evaluation / (static_cast<double>(e.points) * largest_terms);
    e.growth_cpu_seconds = std::max(e.cpu_seconds, kMinGrowthBudgetPasses * seconds_per_pass);
  }
  return e;
}

std::string FitCostEstimate::describe() const {
  return fmt::format("cost estimate: {} points, {} order(s): ~{:.2g} likelihood evaluations at {:.3g} ms each (largest "
                     "order, timed here) = ~{} of CPU, ~{} on {} thread(s) (within a factor ~2; more if orders are "
                     "re-run for missed modes{}); fewer points ({}), a smaller {}/{} or {} cut it",
                     points, orders, evaluations, seconds_per_evaluation * 1e3, duration(cpu_seconds),
                     duration(wall_seconds), threads,
                     growth_cpu_seconds > 0.0
                         ? fmt::format(", and up to ~{} of CPU if the grid grows", duration(growth_cpu_seconds))
                         : std::string(),
                     setting("band"), setting("qmax"), setting("smax"), setting("sampler.live"));
}

}  // namespace admitgen

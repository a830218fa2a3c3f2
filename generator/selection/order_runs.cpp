// SPDX-License-Identifier: MIT
// The nested-sampling runs of a fit's orders: each order as a model of the data (order_model, order_sampler,
// order_seed, with_band_priors: selection/fit.hpp), first runs (split into FitSettings::runs independent parts),
// re-run rounds for missed modes, and their merges (inference/run_merge.hpp; docs/method.md, "Model selection").
#include "selection/order_runs.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "inference/comparison.hpp"
#include "inference/pole_space.hpp"
#include "inference/poles_sampler.hpp"
#include "inference/run_merge.hpp"
#include "model/passivity.hpp"
#include "selection/fit_cost.hpp"
#include "selection/missed_modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace admitgen {

std::uint64_t order_seed(std::uint64_t user_seed, const Order& order) {
  return Comparison::job_seed(user_seed,
                              static_cast<std::uint64_t>(order.q()) * 1000u + static_cast<std::uint64_t>(order.s()));
}

SamplerKind parse_sampler_kind(const std::string& text) {
  if (text == "poles") return SamplerKind::poles;
  if (text == "full") return SamplerKind::full;
  throw InputError(fmt::format("{} '{}': expected poles or full", setting("sampler_kind"), text));
}

Model order_model(const Measurement& data, const Order& order, const FitSettings& settings) {
  const auto transform = std::make_shared<const PriorTransform>(order, settings.priors, settings.reduce_symmetry);
  const auto likelihood = std::make_shared<const Likelihood>(data, order, settings.data_count);
  LogLikelihoodFn log_likelihood = [likelihood](const double* th) { return (*likelihood)(th); };
  if (settings.passive)
    log_likelihood = [likelihood, order](const double* th) {
      return is_passive(order, th) ? (*likelihood)(th) : -std::numeric_limits<double>::infinity();
    };
  return Model{order.parameter_names(), [transform](const double* u, double* th) { (*transform)(u, th); },
               std::move(log_likelihood), [transform](double* u) { transform->fold(u); }};
}

SamplerKind order_sampler(const FitSettings& settings, std::string* note) {
  if (settings.sampler_kind == SamplerKind::full) return SamplerKind::full;
  std::string why;
  if (settings.passive)
    why = "sampling passive models only (" + setting("passive") + ") needs the residues in the sampled space";
  else if (settings.priors.residues == ResiduePrior::uniform)
    why = "the uniform residue prior (" + settings.priors_origin + ") has no closed-form marginal: residues sampled";
  if (why.empty()) return SamplerKind::poles;
  if (note != nullptr) *note = why;
  return SamplerKind::full;
}

FitSettings with_band_priors(FitSettings settings, const Measurement& data) {
  if (settings.priors.band_of_data)
    settings.priors = PriorRanges::band(data.omega().maxCoeff(), settings.priors.admittance_scale);
  return settings;
}

/// Each of an order's first runs needs live points of its own to sample with (kMinLivePerRun).
void check_runs(const FitSettings& settings) {
  constexpr int kMinLivePerRun = 5;
  if (settings.runs < 1 || settings.sampler.live / settings.runs < kMinLivePerRun)
    throw InputError(fmt::format("{} = {} split over {} = {} runs leaves fewer than {} live points per run; lower "
                                 "{} or raise {}",
                                 setting("sampler.live"), settings.sampler.live, setting("runs"), settings.runs,
                                 kMinLivePerRun, setting("runs"), setting("sampler.live")));
}

namespace {

/// Live points of each run that a re-run round adds (the first run has settings.sampler.live).
int part_live(int live) { return std::max(2, (live + 1) / 2); }

/// Independent runs an order's first run is made of: settings.runs, or one where nothing is sampled (an order
/// without poles under the pole sampler, whose evidence is the closed form).
int first_run_parts(const Order& order, const FitSettings& settings) {
  const bool analytic = order_sampler(settings) == SamplerKind::poles && pole_count(order) == 0;
  return analytic ? 1 : std::max(settings.runs, 1);
}

/// Round 0 is an order's first run, `part` one of its first_run_parts, each with its share of the live points
/// (the first ones one more where they do not divide) and the stop of the fit's live points; round r ≥ 1 adds
/// 2^r parts of part_live points each, with the stop of their own. Each part has a stream of its own.
NestedSettings order_sampler_settings(const Order& order, const FitSettings& settings, int round, int part) {
  NestedSettings sampler = settings.sampler;
  if (round == 0) sampler.dlogz = settings.sampler.stop_dlogz();
  const std::uint64_t stream = derive_seed(order_seed(settings.sampler.seed, order), static_cast<std::uint64_t>(round));
  sampler.seed = round == 0 && part == 0 ? stream : derive_seed(stream, static_cast<std::uint64_t>(part) + 1);
  if (round > 0) {
    sampler.live = part_live(settings.sampler.live);
  } else {
    const int parts = first_run_parts(order, settings);
    sampler.live = settings.sampler.live / parts + (part < settings.sampler.live % parts ? 1 : 0);
  }
  return sampler;
}

ModelResult run_full(const Measurement& data, const Order& order, const FitSettings& settings,
                     const NestedProgressFn& progress, const NestedSettings& sampler) {
  ModelResult result{order, run_nested_sampling(order_model(data, order, settings), sampler, progress), sampler.live,
                     0.0, {}};
  result.sampler = "full";
  return result;
}

ModelResult run_poles(const Measurement& data, const Order& order, const FitSettings& settings,
                      const NestedProgressFn& progress, const NestedSettings& sampler) {
  ModelResult result{order,
                     run_poles_sampler(data, order, settings.priors, settings.reduce_symmetry, settings.data_count,
                                       sampler, derive_seed(sampler.seed, 0x7e51dULL), progress),
                     sampler.live, 0.0, {}};
  result.sampler = kPoleSamplerName;
  return result;
}

/// One run of an order, part `part` of round `round` (order_sampler_settings), untimed: what the comparison
/// driver runs (and times) for each run of a fit.
ModelResult run_order(const Measurement& data, const Order& order, const FitSettings& given,
                      const NestedProgressFn& progress, int round, int part) {
  const FitSettings settings = with_band_priors(given, data);
  const NestedSettings sampler = order_sampler_settings(order, settings, round, part);
  std::string note;
  ModelResult result = order_sampler(settings, &note) == SamplerKind::poles
                           ? run_poles(data, order, settings, progress, sampler)
                           : run_full(data, order, settings, progress, sampler);
  result.sampler_note = note;
  for (std::size_t i = 0; i < result.run.size(); ++i)
    fold_to_reduced(order, result.run.samples.data() + i * static_cast<std::size_t>(order.dim()));
  result.parameters = summarize(result.run, order.parameter_names());
  return result;
}

/// The runs `parts` of one order merged into one (inference/run_merge.hpp): live points, calls and times add up;
/// the rest is the first part's. With `scatter` (a fit of independent runs, FitSettings::runs ≥ 2) the error
/// of ln Z is their scatter where it exceeds √(H/n). Summaries are left to the caller.
ModelResult merged(const std::vector<const ModelResult*>& parts, bool scatter) {
  ModelResult out = *parts.front();
  std::vector<RunPart> runs;
  out.live = 0;
  out.seconds = out.cpu_seconds = 0.0;
  for (const ModelResult* p : parts) {
    runs.push_back({&p->run, p->live});
    out.live += p->live;
    out.seconds += p->seconds;
    out.cpu_seconds += p->cpu_seconds;
  }
  out.run = merge_runs(runs);
  if (scatter) out.run.log_z_error = std::max(out.run.log_z_error, scatter_error(runs));
  return out;
}

/// An order's first run from its parts (first_run_parts of them, in part order).
ModelResult first_run(const std::vector<const ModelResult*>& parts) {
  if (parts.size() == 1) return *parts.front();
  ModelResult out = merged(parts, true);
  out.parameters = summarize(out.run, out.order.parameter_names());
  return out;
}

}  // namespace

ModelResult fit_order(const Measurement& data, const Order& order, const FitSettings& settings,
                      const NestedProgressFn& progress) {
  check_runs(settings);
  std::vector<ModelResult> parts;
  std::vector<const ModelResult*> done;
  const int n = first_run_parts(order, with_band_priors(settings, data));
  parts.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const TaskTime time = timed([&] { parts.push_back(run_order(data, order, settings, progress, 0, k)); });
    parts.back().seconds = time.seconds;
    parts.back().cpu_seconds = time.cpu_seconds;
    done.push_back(&parts.back());
  }
  return first_run(done);
}


namespace {

/// One run of the comparison driver: order grid[order]'s first run (round 0) or part `part` of re-run round
/// `round`.
struct RunTask {
  std::size_t order;
  int round = 0, part = 0;
  int parts = 1;  ///< the parts of this task's round for this order (for its label)
};

/// Runs `tasks` on the comparison driver (inference/comparison.hpp), largest order first; returns one result
/// per task, timed.
std::vector<ModelResult> run_tasks(const Measurement& data, const FitSettings& settings, const std::vector<Order>& grid,
                                   const std::vector<RunTask>& tasks, Progress& progress) {
  std::vector<std::size_t> queue(tasks.size());
  std::iota(queue.begin(), queue.end(), std::size_t{0});
  std::stable_sort(queue.begin(), queue.end(),
                   [&](auto a, auto b) { return grid[tasks[a].order].dim() > grid[tasks[b].order].dim(); });
  std::vector<ComparisonJob> jobs;
  for (const RunTask& t : tasks) {
    const Order& o = grid[t.order];
    const NestedSettings sampler = order_sampler_settings(o, settings, t.round, t.part);
    const std::string label = t.round > 0    ? fmt::format("{} (+{})", o.name(), t.part + 1)
                              : t.parts > 1 ? fmt::format("{} ({}/{})", o.name(), t.part + 1, t.parts)
                                            : o.name();
    jobs.push_back({label,
                    expected_work(o, settings, sampler.live), sampler.stop_dlogz()});
  }
  std::vector<ModelResult> results(tasks.size(), ModelResult{Order(0, 0), {}, 0, 0.0, {}});
  Comparison comparison(progress, settings.threads, "runs");
  const auto times = comparison.run(
      jobs, queue,
      [&](std::size_t k, const NestedProgressFn& status) {
        results[k] = run_order(data, grid[tasks[k].order], settings, status, tasks[k].round, tasks[k].part);
      },
      [&](std::size_t k, const TaskTime& time) {
        const ModelResult& m = results[k];
        return fmt::format("  {:<9} ln Z = {:10.2f} ± {:.2f}  ({} calls, {:.1f} s)", jobs[k].label, m.run.log_z,
                           m.run.log_z_error, m.run.calls, time.seconds);
      });
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    results[k].seconds = times[k].seconds;
    results[k].cpu_seconds = times[k].cpu_seconds;
  }
  return results;
}

/// `model` with the runs of a re-run round merged into its run (inference/run_merge.hpp): live points, calls and
/// times add up, and `rerun` holds the round's check, the added runs on their own against the order's run before
/// them (independent estimates of one ln Z); `scatter` as in merged.
ModelResult merged_with(const ModelResult& model, const std::vector<const ModelResult*>& added, bool scatter) {
  const NestedRun fresh = merged(added, scatter).run;
  RerunCheck check;
  check.log_z_shift = fresh.log_z - model.run.log_z;
  check.error = std::hypot(fresh.log_z_error, model.run.log_z_error);
  std::vector<const ModelResult*> all{&model};
  all.insert(all.end(), added.begin(), added.end());
  ModelResult out = merged(all, scatter);
  check.live = out.live - model.live;
  out.parameters = summarize(out.run, model.order.parameter_names());
  out.rerun = check;
  return out;
}

}  // namespace

void run_orders(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                const std::vector<std::size_t>& which, Progress& progress) {
  std::vector<RunTask> tasks;
  for (std::size_t i : which) {
    const int parts = first_run_parts(orders.grid[i], settings);
    for (int k = 0; k < parts; ++k) tasks.push_back({i, 0, k, parts});
  }
  const std::vector<ModelResult> done = run_tasks(data, settings, orders.grid, tasks, progress);
  for (std::size_t i : which) {
    std::vector<const ModelResult*> mine;
    for (std::size_t k = 0; k < tasks.size(); ++k)
      if (tasks[k].order == i) mine.push_back(&done[k]);
    orders.results[i] = first_run(mine);
  }
}

void add_orders(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                const std::vector<Order>& add, Progress& progress) {
  FittedOrders grown;
  grown.grid = orders.grid;
  grown.grid.insert(grown.grid.end(), add.begin(), add.end());
  std::stable_sort(grown.grid.begin(), grown.grid.end(),
                   [](const Order& a, const Order& b) { return a.q() != b.q() ? a.q() < b.q() : a.s() < b.s(); });
  grown.results.assign(grown.grid.size(), ModelResult{Order(0, 0), {}, 0, 0.0, {}});
  grown.rounds.assign(grown.grid.size(), 0);
  std::vector<std::size_t> added;
  for (std::size_t i = 0; i < grown.grid.size(); ++i) {
    const auto old = std::find(orders.grid.begin(), orders.grid.end(), grown.grid[i]);
    if (old == orders.grid.end()) {
      added.push_back(i);
      continue;
    }
    const auto j = static_cast<std::size_t>(old - orders.grid.begin());
    grown.results[i] = std::move(orders.results[j]);
    grown.rounds[i] = orders.rounds[j];
  }
  run_orders(data, settings, grown, added, progress);
  orders = std::move(grown);
}

void rerun_missed_modes(const Measurement& data, const FitSettings& settings, FittedOrders& orders,
                        OrderMarginals& marginals, Progress& progress) {
  std::vector<ModelResult>& results = orders.results;
  for (int round = 1; round <= settings.missed_mode_retries; ++round) {
    std::vector<std::size_t> which;
    for (const MissedMode& m : missed_modes(data, settings, results, marginals))
      if (orders.rounds[m.order] < round && results[m.order].run.stopped_by != "analytic" &&
          !settled(results[m.order], m))
        which.push_back(m.order);
    for (std::size_t i = 0; i < results.size() && settings.runs > 1; ++i)
      if (orders.rounds[i] < round && runs_disagree(results[i]) &&
          std::find(which.begin(), which.end(), i) == which.end())
        which.push_back(i);
    if (which.empty()) continue;
    const int parts = 1 << round;
    progress.message(fmt::format("re-running {} order(s) that missed a mode: {} more runs of {} live points each",
                                 which.size(), parts, part_live(settings.sampler.live)));
    std::vector<RunTask> tasks;
    for (std::size_t i : which)
      for (int k = 0; k < parts; ++k) tasks.push_back({i, round, k});
    const std::vector<ModelResult> done = run_tasks(data, settings, orders.grid, tasks, progress);
    for (std::size_t i : which) {
      std::vector<const ModelResult*> mine;
      for (std::size_t k = 0; k < tasks.size(); ++k)
        if (tasks[k].order == i) mine.push_back(&done[k]);
      results[i] = merged_with(results[i], mine, settings.runs > 1);
      results[i].accuracy.reset();  // a new run: its passive estimate is made again (accuracy_stop.hpp)
      orders.rounds[i] = round;
    }
  }
}

}  // namespace admitgen

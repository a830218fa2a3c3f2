// SPDX-License-Identifier: MIT
#include "selection/fit.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "inference/comparison.hpp"
#include "inference/pole_space.hpp"
#include "inference/poles_sampler.hpp"
#include "inference/run_merge.hpp"
#include "model/multipole.hpp"
#include "model/passivity.hpp"
#include "selection/accuracy_stop.hpp"
#include "selection/fit_cost.hpp"
#include "selection/grid_growth.hpp"
#include "selection/missed_modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>

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

namespace {

/// Each of an order's first runs needs live points of its own to sample with (kMinLivePerRun).
void check_runs(const FitSettings& settings) {
  constexpr int kMinLivePerRun = 5;
  if (settings.runs < 1 || settings.sampler.live / settings.runs < kMinLivePerRun)
    throw InputError(fmt::format("{} = {} split over {} = {} runs leaves fewer than {} live points per run; lower "
                                 "{} or raise {}",
                                 setting("sampler.live"), settings.sampler.live, setting("runs"), settings.runs,
                                 kMinLivePerRun, setting("runs"), setting("sampler.live")));
}

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

}  // namespace

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

namespace {

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

PredictiveBand predictive_band(const Measurement& data, const ModelResult& model, int draws, std::uint64_t seed) {
  Rng rng(seed);
  const auto idx = resample_indices(posterior_weights(model.run), static_cast<std::size_t>(draws), rng);
  const Eigen::ArrayXd omega = data.omega();
  const Eigen::Index n = omega.size();
  Eigen::ArrayXXd re(n, draws), im(n, draws), al(n, draws);
  Eigen::ArrayXd r, i;
  for (int d = 0; d < draws; ++d) {
    evaluate_multipole(model.order, model.run.point(idx[static_cast<std::size_t>(d)]), omega, r, i);
    re.col(d) = r;
    im.col(d) = i;
    Eigen::ArrayXcd g(n);
    g.real() = r;
    g.imag() = i;
    al.col(d) = absorption(g);
  }
  const Eigen::ArrayXd equal = Eigen::ArrayXd::Constant(draws, 1.0);
  PredictiveBand band;
  band.f_hz = data.f_hz;
  band.draws = draws;
  const auto quantiles = [&](const Eigen::ArrayXXd& m, Eigen::ArrayXd& lo, Eigen::ArrayXd& med, Eigen::ArrayXd& hi) {
    lo.resize(n), med.resize(n), hi.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const Eigen::ArrayXd row = m.row(k).transpose();
      lo[k] = weighted_quantile(row, equal, 0.025);
      med[k] = weighted_quantile(row, equal, 0.5);
      hi[k] = weighted_quantile(row, equal, 0.975);
    }
  };
  quantiles(re, band.re_lo, band.re_median, band.re_hi);
  quantiles(im, band.im_lo, band.im_median, band.im_hi);
  quantiles(al, band.alpha_lo, band.alpha_median, band.alpha_hi);
  return band;
}

namespace {

/// The largest order of the grid (Q = qmax, S = smax) must have fewer parameters than real data.
void check_constrainable(const Measurement& data, const FitSettings& settings) {
  const Order largest(settings.qmax, settings.smax);
  const int k = real_data_count(settings.data_count, data.size());
  if (k < largest.dim() + 2)
    throw InputError(fmt::format("{} has {} parameters but the data hold only K = {} real values; lower "
                                 "{}/{} or supply more frequency points",
                                 largest.name(), largest.dim(), k, setting("qmax"), setting("smax")));
}

}  // namespace


std::vector<Eigen::VectorXd> best_samples(const ModelResult& model, int n) {
  const NestedRun& run = model.run;
  std::vector<std::size_t> idx(run.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  const std::size_t k = std::min(idx.size(), static_cast<std::size_t>(std::max(n, 0)));
  // Ties broken by index, so the choice is deterministic.
  std::partial_sort(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(k), idx.end(), [&](std::size_t a, std::size_t b) {
    return run.log_likelihood[a] > run.log_likelihood[b] || (run.log_likelihood[a] == run.log_likelihood[b] && a < b);
  });
  std::vector<Eigen::VectorXd> out;
  for (std::size_t i = 0; i < k; ++i)
    out.emplace_back(Eigen::Map<const Eigen::VectorXd>(run.point(idx[i]), model.order.dim()));
  return out;
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

/// First runs of the orders grid[i] for i in `which`, written to results[i].
void run_orders(const Measurement& data, const FitSettings& settings, const std::vector<Order>& grid,
                const std::vector<std::size_t>& which, std::vector<ModelResult>& results, Progress& progress) {
  std::vector<RunTask> tasks;
  for (std::size_t i : which) {
    const int parts = first_run_parts(grid[i], settings);
    for (int k = 0; k < parts; ++k) tasks.push_back({i, 0, k, parts});
  }
  const std::vector<ModelResult> done = run_tasks(data, settings, grid, tasks, progress);
  for (std::size_t i : which) {
    std::vector<const ModelResult*> mine;
    for (std::size_t k = 0; k < tasks.size(); ++k)
      if (tasks[k].order == i) mine.push_back(&done[k]);
    results[i] = first_run(mine);
  }
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

/// Re-runs orders that missed a mode (missed_modes), in rounds r = 1 … missed_mode_retries: round r adds 2^r
/// runs of part_live points on streams of their own to the order's run and merges them with it
/// (inference/run_merge.hpp), so that after round r it holds about 2^r times the live points, as one run of
/// that many would, at half the calls of such a run and with its parts in parallel. An order runs round r at
/// most once (`rounds[i]`: the last round order i ran), so calling this again after the grid grew re-runs only
/// what the new orders reveal. An order without poles (its evidence analytic) has no mode to miss.
void rerun_missed_modes(const Measurement& data, const FitSettings& settings, const std::vector<Order>& grid,
                        std::vector<ModelResult>& results, std::vector<int>& rounds, Progress& progress) {
  for (int round = 1; round <= settings.missed_mode_retries; ++round) {
    std::vector<std::size_t> which;
    for (const MissedMode& m : missed_modes(data, settings, results))
      if (rounds[m.order] < round && results[m.order].run.stopped_by != "analytic" && !settled(results[m.order], m))
        which.push_back(m.order);
    for (std::size_t i = 0; i < results.size() && settings.runs > 1; ++i)
      if (rounds[i] < round && runs_disagree(results[i]) && std::find(which.begin(), which.end(), i) == which.end())
        which.push_back(i);
    if (which.empty()) continue;
    const int parts = 1 << round;
    progress.message(fmt::format("re-running {} order(s) that missed a mode: {} more runs of {} live points each",
                                 which.size(), parts, part_live(settings.sampler.live)));
    std::vector<RunTask> tasks;
    for (std::size_t i : which)
      for (int k = 0; k < parts; ++k) tasks.push_back({i, round, k});
    const std::vector<ModelResult> done = run_tasks(data, settings, grid, tasks, progress);
    for (std::size_t i : which) {
      std::vector<const ModelResult*> mine;
      for (std::size_t k = 0; k < tasks.size(); ++k)
        if (tasks[k].order == i) mine.push_back(&done[k]);
      results[i] = merged_with(results[i], mine, settings.runs > 1);
      results[i].accuracy.reset();  // a new run: its passive estimate is made again (accuracy_stop.hpp)
      rounds[i] = round;
    }
  }
}

/// Grows the fitted orders while the selected one lies on their edge and its passive estimate misses the accuracy
/// target (selection/grid_growth.hpp, selection/accuracy_stop.hpp): runs the added orders (and the re-runs they
/// call for), estimates their passive models, and keeps `grid`, `results` and `rounds` in Q-major order.
/// `would_grow` is set when the target stopped a growth the evidence asked for.
GridGrowth grow_grid(const Measurement& data, const FitSettings& settings, std::vector<Order>& grid,
                     std::vector<ModelResult>& results, std::vector<int>& rounds, double first_round_passes,
                     const passivity::LazyPassiveBound& bound, bool& would_grow, Progress& progress) {
  GridGrowth growth{settings.qmax, settings.smax, {}, {}};
  const int k = real_data_count(settings.data_count, data.size());
  const double budget = std::max(first_round_passes, kMinGrowthBudgetPasses);
  double spent = 0.0;
  for (;;) {
    estimate_passive(data, settings, results, bound);
    const std::size_t selected = select_usable(settings, results);
    auto step = next_grid_step(results, selected, settings, k, static_cast<long>(data.size()), spent, budget,
                               growth.edge);
    if (step && settings.max_buffers > 0) {
      const auto over = [&](const Order& o) { return o.buffers() > settings.max_buffers; };
      step->add.erase(std::remove_if(step->add.begin(), step->add.end(), over), step->add.end());
      if (step->add.empty()) {
        growth.edge = fmt::format("{} lies on the edge of the fitted orders and the evidence still rises, but the "
                                  "next orders exceed the budget of {} buffers per node ({})",
                                  results[selected].order.name(), settings.max_buffers, setting("max_buffers"));
        step.reset();
      }
    }
    const auto& accuracy = results[selected].accuracy;
    if (accuracy && accuracy->meets) {
      would_grow = step.has_value() || !growth.edge.empty();
      growth.edge.clear();  // the target is met: larger orders are a note, not a warning
      return growth;
    }
    if (!step) return growth;
    progress.message(step->reason);
    growth.steps.push_back(step->reason);
    spent += step->passes;
    std::vector<Order> grown = grid;
    grown.insert(grown.end(), step->add.begin(), step->add.end());
    std::stable_sort(grown.begin(), grown.end(),
                     [](const Order& a, const Order& b) { return a.q() != b.q() ? a.q() < b.q() : a.s() < b.s(); });
    std::vector<ModelResult> merged(grown.size(), ModelResult{Order(0, 0), {}, 0, 0.0, {}});
    std::vector<int> merged_rounds(grown.size(), 0);
    std::vector<std::size_t> added;
    for (std::size_t i = 0; i < grown.size(); ++i) {
      const auto old = std::find(grid.begin(), grid.end(), grown[i]);
      if (old == grid.end()) {
        added.push_back(i);
        continue;
      }
      const auto j = static_cast<std::size_t>(old - grid.begin());
      merged[i] = std::move(results[j]);
      merged_rounds[i] = rounds[j];
    }
    run_orders(data, settings, grown, added, merged, progress);
    grid = std::move(grown);
    results = std::move(merged);
    rounds = std::move(merged_rounds);
    for (const Order& o : step->add) {
      growth.qmax = std::max(growth.qmax, o.q());
      growth.smax = std::max(growth.smax, o.s());
    }
    rerun_missed_modes(data, settings, grid, results, rounds, progress);
  }
}

}  // namespace

FitResult run_fit(const Measurement& data, const FitSettings& settings, Progress& progress) {
  return complete_fit(data, settings, run_first_round(data, settings, progress), progress);
}

std::vector<ModelResult> run_first_round(const Measurement& data, const FitSettings& given, Progress& progress) {
  const FitSettings settings = with_band_priors(given, data);
  const std::vector<Order> grid = order_grid(settings.qmax, settings.smax);
  check_constrainable(data, settings);
  check_runs(settings);
  std::vector<ModelResult> results(grid.size(), ModelResult{Order(0, 0), {}, 0, 0.0, {}});
  std::vector<std::size_t> which(grid.size());
  std::iota(which.begin(), which.end(), std::size_t{0});
  run_orders(data, settings, grid, which, results, progress);
  return results;
}

FitResult complete_fit(const Measurement& data, const FitSettings& given, std::vector<ModelResult> results,
                       Progress& progress) {
  const FitSettings settings = with_band_priors(given, data);
  std::vector<Order> grid = order_grid(settings.qmax, settings.smax);
  check_constrainable(data, settings);
  if (results.size() != grid.size())
    throw std::logic_error("complete_fit: one first-round result per order of the grid expected");
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (results[i].order != grid[i]) throw std::logic_error("complete_fit: results not in grid order");
  double first_round_passes = 0.0;
  for (const auto& m : results)
    first_round_passes += pole_passes(m.order, static_cast<double>(m.run.calls), static_cast<long>(data.size()));
  std::vector<int> rounds(grid.size(), 0);
  rerun_missed_modes(data, settings, grid, results, rounds, progress);

  FitResult fit;
  const passivity::LazyPassiveBound bound(data);
  bool would_grow = false;
  fit.grid = grow_grid(data, settings, grid, results, rounds, first_round_passes, bound, would_grow, progress);
  estimate_passive(data, settings, results, bound);
  fit.selected = select_usable(settings, results);
  fit.models = std::move(results);
  const std::vector<MissedMode> missed = missed_modes(data, settings, fit.models);
  fit.warnings = missed_mode_warnings(fit.models, missed);
  fit.notes = missed_mode_notes(fit.models, missed);
  if (settings.runs > 1)
    for (std::string& w : runs_disagree_warnings(fit.models)) fit.warnings.push_back(std::move(w));
  if (!fit.grid.edge.empty()) fit.warnings.push_back(fit.grid.edge);
  if (auto note = target_met_note(data, settings, fit.models, fit.selected, would_grow); !note.empty())
    fit.notes.push_back(std::move(note));
  if (auto w = target_missed_warning(settings, fit.models, fit.selected); !w.empty()) fit.warnings.push_back(std::move(w));
  if (const auto w = passivity::passivity_cost_warning(fit.models[fit.selected].order, fit.models[fit.selected].passive);
      !w.empty())
    fit.warnings.push_back(w);
  if (const auto w = passivity::conditioning_warning(fit.models[fit.selected].order, fit.models[fit.selected].passive);
      !w.empty())
    fit.warnings.push_back(w);
  if (const auto d = passivity::data_passivity(data); d.negative_points > 0)
    fit.warnings.push_back(fmt::format(
        "the data are not passive at {} of {} points (Re y down to {:.3g}; a wall cannot return more energy than it "
        "receives): noise on a nearly rigid sample, or a calibration error; every passive estimate is the closest "
        "passive model to these data",
        d.negative_points, data.size(), d.min_re));
  constexpr int kPredictiveDraws = 1000;
  fit.predictive = predictive_band(data, fit.models[fit.selected], kPredictiveDraws,
                                   derive_seed(settings.sampler.seed, 0xbadULL));
  return fit;
}

}  // namespace admitgen

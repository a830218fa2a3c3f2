// SPDX-License-Identifier: MIT
#include "diagnosis/effect_identification.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "diagnosis/residual_whiteness.hpp"
#include "inference/comparison.hpp"
#include "inference/evidence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>

namespace admitgen::diagnosis {
namespace {

/// Evidence, posterior and best ϑ of one candidate from its run. Under a reference density the run's
/// likelihood is L/q: its posterior weights are those of L (docs/method.md), its best point is found
/// on ln L = ln(L/q) + ln q.
void take_run(const NestedRun& run, const Model& model, const EffectCandidate& candidate, EffectResult& r) {
  r.log_z = run.log_z;
  r.log_z_error = run.log_z_error;
  r.max_log_likelihood = run.max_log_likelihood;
  r.calls = run.calls;
  if (run.dim == 0) return;
  r.parameters = summarize(run, model.parameter_names);
  std::size_t best = max_likelihood_index(run);
  if (!candidate.reference.empty()) {
    r.max_log_likelihood = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < run.size(); ++i) {
      const double log_l = run.log_likelihood[i] + reference_log_density(candidate, run.point(i));
      if (log_l > r.max_log_likelihood) r.max_log_likelihood = log_l, best = i;
    }
  }
  const double* p = run.point(best);
  r.best.assign(p, p + run.dim);
}

/// The leader every sampled candidate is held to: the best of a known floor (no effect) and the
/// quadrature candidates' evidences. Its value depends on no schedule; a sampled run that reaches its first
/// early-stop check before every quadrature candidate is done waits for it.
class Leader {
 public:
  Leader(std::size_t pending, double floor) : pending_(pending), value_(floor) {}
  void add(double log_z) {
    std::lock_guard<std::mutex> lock(mutex_);
    value_ = std::max(value_, log_z);
    if (--pending_ == 0) done_.notify_all();
  }
  double wait() {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    return value_;
  }

 private:
  std::size_t pending_;
  double value_;
  std::mutex mutex_;
  std::condition_variable done_;
};

/// Adds its evidence to the leader when it goes out of scope, also when the candidate threw (then −∞),
/// so no sampled run waits forever.
struct LeaderShare {
  Leader& leader;
  double log_z = -std::numeric_limits<double>::infinity();
  ~LeaderShare() { leader.add(log_z); }
};

/// Start order of the candidates: the costliest sampled ones first on all workers but one, then every
/// quadrature candidate, then the remaining sampled ones. A sampled run may wait for the leader, which
/// needs every quadrature candidate done; at most workers − 1 sampled runs start before the last of them,
/// so one worker is always free for them. Cost: dimension × the time of one likelihood call (timing only
/// orders the work; it changes no result), timed at the second call: the first builds what a candidate
/// builds on first use (a simulated member's table), on all workers.
std::vector<std::size_t> schedule(const std::vector<EffectCandidate>& candidates, const EffectLikelihood& likelihood,
                                  const std::vector<std::size_t>& cheap, std::vector<std::size_t> sampled, int threads) {
  const auto call_at_centre = [&](std::size_t i) {
    const Model model = effect_model(candidates[i], likelihood);
    std::vector<double> u(static_cast<std::size_t>(model.dim()), 0.5), theta(u.size());
    model.prior_transform(u.data(), theta.data());
    const auto start = std::chrono::steady_clock::now();
    (void)model.log_likelihood(theta.data());
    return static_cast<double>(model.dim()) *
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  run_in_parallel(sampled, threads, [&](std::size_t i) { (void)call_at_centre(i); });
  std::vector<double> cost(candidates.size(), 0.0);
  for (std::size_t i : sampled) cost[i] = call_at_centre(i);
  std::stable_sort(sampled.begin(), sampled.end(), [&](auto a, auto b) { return cost[a] > cost[b]; });
  const std::size_t ahead = std::min(sampled.size(), worker_count(threads, candidates.size()) - 1);
  std::vector<std::size_t> queue(sampled.begin(), sampled.begin() + static_cast<std::ptrdiff_t>(ahead));
  queue.insert(queue.end(), cheap.begin(), cheap.end());
  queue.insert(queue.end(), sampled.begin() + static_cast<std::ptrdiff_t>(ahead), sampled.end());
  return queue;
}

/// Whether a candidate's evidence is sampled (else closed form or quadrature; evaluate()).
bool is_sampled(const EffectCandidate& e, const IdentificationSettings& settings) {
  const std::size_t dim = e.priors.size();
  return !(dim == 0 || (dim == 1 && settings.use_quadrature));
}

EffectResult start_result(const EffectCandidate& e) {
  EffectResult r;
  r.name = e.name;
  r.priors = e.priors;
  r.fixed = e.fixed;
  return r;
}

/// Called by each job of evaluate() at its end, on its worker: i and its result (null when it threw).
using JobEnd = std::function<void(std::size_t, const EffectResult*)>;

/// evaluate_candidates with candidate i on seed stream streams[i]; `then` (may be empty) ends every job.
std::vector<EffectResult> evaluate(const std::vector<EffectCandidate>& candidates, const EffectLikelihood& likelihood,
                                   const IdentificationSettings& settings, double log_z_floor,
                                   const std::vector<std::uint64_t>& streams, Progress& progress,
                                   const JobEnd& then = {});

/// Whether an early-stop bound lies more than settings.early_stop_deciban below the leader.
using BelowLeader = std::function<bool(double bound)>;

/// The nested-sampling run of a sampled candidate on seed stream `stream`, into r. Once early stop is
/// allowed (settings.early_stop_deciban > 0) the run stops when below_leader(its bound), which may block
/// until the leader is known. `abandon` (may be empty), asked after every death, ends the run
/// unfinished: returns false then, and r is not a result.
bool run_sampled(const EffectCandidate& candidate, const EffectLikelihood& likelihood,
                 const IdentificationSettings& settings, std::uint64_t stream, const BelowLeader& below_leader,
                 const std::function<bool()>& abandon, const NestedProgressFn& status, EffectResult& r) {
  r.method = "nested_sampling";
  NestedSettings sampler = settings.sampler;
  sampler.seed = Comparison::job_seed(settings.sampler.seed, stream);
  bool abandoned = false;
  const NestedStopFn stop = [&](const NestedStatus& s) {
    if (abandon && abandon()) {
      abandoned = true;
      return true;
    }
    if (settings.early_stop_deciban <= 0.0 || !early_stop_allowed(s, sampler.live)) return false;
    const double bound = early_stop_bound(s);
    if (!below_leader(bound)) return false;
    r.stopped_early = true;
    r.log_z_bound = bound;
    return true;
  };
  const Model model = effect_model(candidate, likelihood);
  const NestedRun run = run_nested_sampling(model, sampler, status, stop);
  if (abandoned) return false;
  take_run(run, model, candidate, r);
  return true;
}

}  // namespace

Model effect_model(const EffectCandidate& e, const EffectLikelihood& likelihood) {
  std::vector<std::string> names;
  for (const auto& p : e.priors) names.push_back(p.name);
  if (e.reference.empty())
    return Model{std::move(names),
                 [&e](const double* u, double* theta) {
                   for (std::size_t k = 0; k < e.priors.size(); ++k) theta[k] = e.priors[k].transform(u[k]);
                 },
                 [&e, &likelihood](const double* theta) { return likelihood(e.predict(theta)); }};
  ADMITGEN_ENSURE(e.reference.size() == e.priors.size(), "one reference density per parameter");
  // The cube is q's (u = Q⁻¹(v)); the likelihood is L/q (docs/method.md, "Reference priors in the
  // combined search").
  return Model{std::move(names),
               [&e](const double* v, double* theta) {
                 for (std::size_t k = 0; k < e.priors.size(); ++k)
                   theta[k] = e.priors[k].transform(e.reference[k].inverse_cdf(v[k]));
               },
               [&e, &likelihood](const double* theta) {
                 return likelihood(e.predict(theta)) - reference_log_density(e, theta);
               }};
}

std::vector<ReferenceDensity> reference_densities(const std::vector<ParameterPrior>& priors,
                                                  const std::vector<ParameterSummary>& posterior, double uniform_share) {
  std::vector<ReferenceDensity> out(priors.size());
  if (posterior.size() != priors.size()) return out;
  for (std::size_t k = 0; k < priors.size(); ++k)
    out[k] = ReferenceDensity::from_interval(priors[k].cdf(posterior[k].ci95_lo), priors[k].cdf(posterior[k].ci95_hi),
                                             kReferenceWidening, uniform_share);
  return out;
}

double reference_log_density(const EffectCandidate& e, const double* theta) {
  double out = 0.0;
  for (std::size_t k = 0; k < e.reference.size(); ++k) out += e.reference[k].log_density(e.priors[k].cdf(theta[k]));
  return out;
}

std::string describe_evidence_methods(const IdentificationSettings& s) {
  std::string text = fmt::format(
      "no parameter: the likelihood (closed_form); one: Gauss-Kronrod quadrature over the prior to a relative "
      "error {:g} of Z (quadrature); two or more: nested sampling (nested_sampling)",
      s.quadrature.tolerance);
  if (s.early_stop_deciban > 0.0)
    text += fmt::format("; a sampled effect stops early once its live points fill less than 1/live^2 of the prior "
                        "and 2 max ln L(live) - ln L(contour) stays {:g} deciban below the best evidence of the "
                        "quadrature effects and no effect",
                        s.early_stop_deciban);
  if (s.screen_live < s.sampler.live)
    text += fmt::format("; a round of the combined search screens its joint effects by nested sampling with {} live "
                        "points and runs in full those within {:g} deciban of the best or of decisive",
                        s.screen_live, kScreenDeciban);
  text += fmt::format("; a joint effect of the combined search samples from a reference density on its prior "
                      "(earlier posteriors widened {:g}x plus a uniform share) with the likelihood divided by it, "
                      "the same evidence",
                      kReferenceWidening);
  if (s.pair_exchanges > 0)
    text += fmt::format("; when the combined search ends with structure left, two members at a time are taken out "
                        "and regrown (at most {} times)",
                        s.pair_exchanges);
  return text;
}

double early_stop_bound(const NestedStatus& s) { return 2.0 * s.log_l_max_live - s.log_l_contour; }

bool early_stop_allowed(const NestedStatus& s, int live) { return s.log_x <= -2.0 * std::log(static_cast<double>(live)); }

std::vector<EffectResult> evaluate_candidates(const std::vector<EffectCandidate>& candidates,
                                              const EffectLikelihood& likelihood, const IdentificationSettings& settings,
                                              double log_z_floor, std::uint64_t first_stream, Progress& progress) {
  std::vector<std::uint64_t> streams(candidates.size());
  std::iota(streams.begin(), streams.end(), first_stream);
  return evaluate(candidates, likelihood, settings, log_z_floor, streams, progress);
}

namespace {

std::vector<EffectResult> evaluate(const std::vector<EffectCandidate>& candidates, const EffectLikelihood& likelihood,
                                   const IdentificationSettings& settings, double log_z_floor,
                                   const std::vector<std::uint64_t>& streams, Progress& progress, const JobEnd& then) {
  std::vector<EffectResult> results(candidates.size());
  std::vector<std::size_t> cheap, sampled;
  for (std::size_t i = 0; i < candidates.size(); ++i) (is_sampled(candidates[i], settings) ? sampled : cheap).push_back(i);
  Leader leader(cheap.size(), log_z_floor);
  const auto by_quadrature = [&](std::size_t i, EffectResult& r) {
    LeaderShare share{leader};  // reports this evidence (−∞ if it throws) when it goes out of scope
    r.method = candidates[i].priors.empty() ? "closed_form" : "quadrature";
    const Model model = effect_model(candidates[i], likelihood);
    take_run(evidence_by_quadrature(model, settings.quadrature), model, candidates[i], r);
    share.log_z = r.log_z;
  };
  const auto by_sampling = [&](std::size_t i, EffectResult& r, const NestedProgressFn& status) {
    run_sampled(
        candidates[i], likelihood, settings, streams[i],
        [&](double bound) { return deciban(bound, leader.wait()) < -settings.early_stop_deciban; }, {}, status, r);
  };
  // The work of a candidate for the time left: a quadrature candidate counts 1, a sampled one 10 per parameter.
  std::vector<ComparisonJob> jobs;
  for (const auto& c : candidates)
    jobs.push_back({c.label(), is_sampled(c, settings) ? 10.0 * static_cast<double>(c.priors.size()) : 1.0,
                    settings.sampler.stop_dlogz()});
  Comparison comparison(progress, settings.threads, "candidates");
  const std::vector<TaskTime> times = comparison.run(
      jobs, schedule(candidates, likelihood, cheap, sampled, settings.threads),
      [&](std::size_t i, const NestedProgressFn& status) {
        try {
          results[i] = start_result(candidates[i]);
          if (std::find(cheap.begin(), cheap.end(), i) != cheap.end()) by_quadrature(i, results[i]);
          else by_sampling(i, results[i], status);
        } catch (...) {
          if (then) then(i, nullptr);
          throw;
        }
        if (then) then(i, &results[i]);
      });
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    results[i].seconds = times[i].seconds;
    results[i].cpu_seconds = times[i].cpu_seconds;
  }
  return results;
}


/// The candidate a contender's full run samples: the screened candidate with reference densities built
/// on its screening run's posterior (the same evidence, docs/method.md).
EffectCandidate full_candidate(const EffectCandidate& candidate, const EffectResult& screened) {
  EffectCandidate out = candidate;
  if (out.priors.size() >= 2) out.reference = reference_densities(out.priors, screened.parameters, kReferenceShareJoint);
  return out;
}

/// Full runs of contenders started while their round's screening still runs (evaluate_contenders), so
/// that a round's full run no longer runs alone after its screening with the other workers idle. Once
/// half of the round's screenings have ended, a worker that ends a screening job goes on to the full run
/// of the best screened candidate in contention (within kScreenDeciban of the best screened so far and
/// of decisive) that has none yet, while the other workers screen the rest; waiting for half keeps the
/// runs that a later screening overtakes rare. The run is exactly the one the round would run after its
/// screening: the same candidate, seed stream and reference densities, and its early stop answers as
/// the leader of the round's full runs would (below_leader). A run whose candidate falls out of
/// contention as more screenings end is abandoned: contention only narrows, so it would not have run.
/// So the results are those of screening first and full runs after, at any thread count; only where the
/// time goes changes. At most workers − 1 such runs go at once, so a worker is always left to screen
/// (a full run may wait for the last screening).
class EarlyFullRuns {
 public:
  EarlyFullRuns(const std::vector<EffectCandidate>& candidates, const EffectLikelihood& likelihood,
                const IdentificationSettings& settings, double log_z_reference, std::uint64_t first_stream)
      : candidates_(candidates), likelihood_(likelihood), settings_(settings), first_stream_(first_stream),
        reference_(log_z_reference), floor_(log_z_reference),
        target_(log_z_reference + kDecisiveDeciban * std::log(10.0) / 10.0), done_(candidates.size(), false),
        log_z_(candidates.size(), -std::numeric_limits<double>::infinity()), abandoned_(candidates.size()),
        runs_(candidates.size()), started_(candidates.size(), false), running_(candidates.size(), false),
        posterior_(candidates.size()),
        slots_(static_cast<int>(worker_count(settings.threads, candidates.size())) - 1) {}

  /// The end of candidate i's screening job (r null when it threw). Once half the screenings have ended,
  /// the worker goes on to the full run of the best screened candidate in contention that has none yet.
  void screened(std::size_t i, const EffectResult* r) {
    std::size_t best = candidates_.size();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++screened_;
      done_[i] = true;
      if (r) {
        log_z_[i] = r->log_z;
        target_ = std::max(target_, r->log_z);
        posterior_[i] = r->parameters;
      }
      for (std::size_t j = 0; j < candidates_.size(); ++j)  // the screened ones that fell behind
        if (std::isfinite(log_z_[j]) && !in_contention(j)) abandoned_[j] = true;
      if (screened_ == candidates_.size()) {
        for (std::size_t j = 0; j < candidates_.size(); ++j)
          if (!is_sampled(candidates_[j], settings_) && in_contention(j)) floor_ = std::max(floor_, log_z_[j]);
        all_screened_.notify_all();
      }
      // An abandoned run ends at its next death: it holds no slot.
      int going = 0;
      for (std::size_t j = 0; j < candidates_.size(); ++j) going += started_[j] && running_[j] && !abandoned_[j];
      if (2 * screened_ < candidates_.size() || going >= slots_) return;
      for (std::size_t j = 0; j < candidates_.size(); ++j)
        if (done_[j] && !started_[j] && is_sampled(candidates_[j], settings_) && in_contention(j) &&
            (best == candidates_.size() || log_z_[j] > log_z_[best]))
          best = j;
      if (best == candidates_.size()) return;
      started_[best] = running_[best] = true;
    }
    EffectResult screened_run;
    screened_run.parameters = posterior_[best];
    const EffectCandidate full = full_candidate(candidates_[best], screened_run);
    EffectResult run = start_result(full);
    const bool finished = run_sampled(
        full, likelihood_, settings_, first_stream_ + best, [this](double bound) { return below_leader(bound); },
        [this, best] { return abandoned_[best].load(); }, {}, run);
    std::lock_guard<std::mutex> lock(mutex_);
    running_[best] = false;
    if (finished) runs_[best] = std::move(run);
  }

  /// Candidate i's full run if it ran to its end here (call after every screening job has returned).
  std::optional<EffectResult>& run(std::size_t i) { return runs_[i]; }

 private:
  /// Within kScreenDeciban of the target (needs mutex_).
  bool in_contention(std::size_t j) const { return deciban(log_z_[j], target_) >= -kScreenDeciban; }
  /// Whether `bound` lies more than early_stop_deciban below the leader of the round's full runs:
  /// log_z_reference or the largest evidence of the quadrature candidates if that one stays in contention.
  /// Decided as soon as both possible leaders give the same answer (every quadrature candidate screened:
  /// the schedule runs them first); else it waits for the last screening.
  bool below_leader(double bound) {
    const auto below = [&](double leader) { return deciban(bound, leader) < -settings_.early_stop_deciban; };
    std::unique_lock<std::mutex> lock(mutex_);
    double q_max = -std::numeric_limits<double>::infinity();
    bool known = true;
    for (std::size_t j = 0; j < candidates_.size(); ++j)
      if (!is_sampled(candidates_[j], settings_)) {
        known = known && done_[j];
        q_max = std::max(q_max, log_z_[j]);
      }
    if (known) {
      // Out of contention now is out for good (the target only rises): the leader is log_z_reference.
      if (deciban(q_max, target_) < -kScreenDeciban) return below(reference_);
      if (below(reference_) == below(std::max(reference_, q_max))) return below(reference_);
    }
    all_screened_.wait(lock, [this] { return screened_ == candidates_.size(); });
    return below(floor_);
  }

  const std::vector<EffectCandidate>& candidates_;
  const EffectLikelihood& likelihood_;
  const IdentificationSettings& settings_;
  std::uint64_t first_stream_;
  std::mutex mutex_;
  std::condition_variable all_screened_;
  std::size_t screened_ = 0;
  double reference_, floor_, target_;  ///< log_z_reference; the leader once all are screened; the target so far
  std::vector<bool> done_;             ///< screened
  std::vector<double> log_z_;
  std::vector<std::atomic<bool>> abandoned_;
  std::vector<std::optional<EffectResult>> runs_;
  std::vector<bool> started_, running_;  ///< its full run begun; going on
  std::vector<std::vector<ParameterSummary>> posterior_;  ///< of its screening run
  int slots_;
};

}  // namespace

std::vector<EffectResult> evaluate_contenders(const std::vector<EffectCandidate>& candidates,
                                              const EffectLikelihood& likelihood, const IdentificationSettings& settings,
                                              double log_z_reference, std::uint64_t first_stream, Progress& progress) {
  if (settings.screen_live >= settings.sampler.live)
    return evaluate_candidates(candidates, likelihood, settings, log_z_reference, first_stream, progress);
  IdentificationSettings screening = settings;
  screening.sampler.live = std::max(settings.screen_live, 2);
  EarlyFullRuns early(candidates, likelihood, settings, log_z_reference, first_stream);
  std::vector<std::uint64_t> screen_streams(candidates.size());
  std::iota(screen_streams.begin(), screen_streams.end(), first_stream);
  std::vector<EffectResult> results =
      evaluate(candidates, likelihood, screening, log_z_reference, screen_streams, progress,
               [&](std::size_t i, const EffectResult* r) { early.screened(i, r); });
  double target = log_z_reference + kDecisiveDeciban * std::log(10.0) / 10.0;
  for (const auto& r : results) target = std::max(target, r.log_z);
  std::vector<std::size_t> contenders, late;
  std::vector<EffectCandidate> full;
  std::vector<std::uint64_t> streams;  // each contender keeps its seed stream first_stream + i
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (results[i].method == "nested_sampling") results[i].method = "screened";
    if (deciban(results[i].log_z, target) < -kScreenDeciban) continue;
    contenders.push_back(i);
    if (early.run(i)) continue;  // its full run went while the others were screened (EarlyFullRuns)
    late.push_back(i);
    full.push_back(full_candidate(candidates[i], results[i]));
    streams.push_back(first_stream + i);
  }
  std::vector<EffectResult> runs = evaluate(full, likelihood, settings, log_z_reference, streams, progress);
  for (std::size_t k = 0; k < late.size(); ++k) early.run(late[k]) = std::move(runs[k]);
  for (std::size_t i : contenders) {
    // The early runs' time is already in their screening job's.
    EffectResult& r = *early.run(i);
    const EffectResult& screened = results[i];
    const bool ran_late = std::find(late.begin(), late.end(), i) != late.end();
    r.seconds = ran_late ? r.seconds + screened.seconds : screened.seconds;
    r.cpu_seconds = ran_late ? r.cpu_seconds + screened.cpu_seconds : screened.cpu_seconds;
    r.calls += screened.calls;
    results[i] = std::move(r);
  }
  return results;
}

void fill_gap(EffectResult& r, const EffectCandidate& candidate, const Eigen::ArrayXd& f_hz,
              const Eigen::ArrayXcd& y_real, const Gap& gap_before) {
  const EffectPrediction p = candidate.predict(r.best.empty() ? nullptr : r.best.data());
  r.gap_after = measure_gap(f_hz, y_real, p.y, rms_level(y_real));
  // With a noise shape the residual's points have unequal variances, which the lag-1 test assumes equal
  // (a few noisy points dominate ρ₁ and |z| ≥ 3 far more often than 0.3 %): it tests the residual in
  // units of its own noise, (y_real − y)/s_i (docs/diagnosis.md, "Combined explanations").
  if (p.noise_shape.size() > 0) r.gap_after.whiteness = residual_whiteness((y_real - p.y) / p.noise_shape);
  r.shrink = gap_before.total / r.gap_after.total;
  r.explained = 1.0 - 1.0 / (r.shrink * r.shrink);
  r.band = most_improved_band(gap_before.bands, r.gap_after.bands);
}

Identification identify_effects(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
                                const Eigen::ArrayXcd& y_sim, const Gap& gap_before,
                                const std::vector<EffectCandidate>& candidates, const IdentificationSettings& settings,
                                Progress& progress) {
  const EffectLikelihood likelihood(y_real);
  Identification out;
  out.log_z_none = likelihood(EffectPrediction{y_sim, {}});
  out.effects = evaluate_candidates(candidates, likelihood, settings, out.log_z_none, 0, progress);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    out.effects[i].candidate = i;
    fill_gap(out.effects[i], candidates[i], f_hz, y_real, gap_before);
  }
  std::stable_sort(out.effects.begin(), out.effects.end(),
                   [](const EffectResult& a, const EffectResult& b) { return a.log_z > b.log_z; });
  for (auto& r : out.effects) r.bayes_factor_deciban = deciban(r.log_z, out.log_z_none);
  return out;
}

}  // namespace admitgen::diagnosis

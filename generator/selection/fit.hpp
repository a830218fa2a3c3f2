// SPDX-License-Identifier: MIT
/// @file
/// Order selection over the grid Q ∈ [0, qmax] × S ∈ [0, smax]: one nested-sampling run per order
/// (in parallel over orders, each order with its own seed stream so results do not depend on the
/// thread count), Bayes factors, the selection rule, the selected order's parameter summaries and
/// the posterior band of its model curve G(ω) and α(f).
#pragma once

#include "core/progress.hpp"
#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/posterior.hpp"
#include "inference/priors.hpp"
#include "model/order.hpp"
#include "passivity/passive_estimate.hpp"
#include "selection/accuracy_target.hpp"
#include "selection/selection_rule.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace admitgen {

/// How each order is sampled: `poles` integrates the residues and the noise out exactly under the Gaussian
/// residue prior and samples the poles only (inference/poles_sampler.hpp); `full` samples every parameter
/// (docs/method.md, "Samplers"). The uniform residue prior (Table 1) and `passive` fits need `full`
/// (order_sampler says which runs).
enum class SamplerKind { poles, full };
SamplerKind parse_sampler_kind(const std::string& text);  ///< "full" | "poles"

/// The nested-sampling settings of a fit by default (NestedSettings with 300 live points).
inline NestedSettings default_fit_sampler() {
  NestedSettings s;
  s.live = 300;
  return s;
}

struct FitSettings {
  int qmax = 3;
  int smax = 3;
  /// live, dlogz, max_iterations, slices, seed (the user seed). 300 live points by default: on the bundled
  /// Basotect data 100 lose modes of mid orders by 3-9 nats while two seeds at 300 agree (docs/validation.md,
  /// "Fitting"), and 500 cost 5/3 as much for errors smaller than the orders' differences.
  NestedSettings sampler = default_fit_sampler();
  /// The priors (PriorRanges::band_of_data: the pole ranges follow the data, with_band_priors).
  PriorRanges priors = PriorRanges::band_of_the_data();
  std::string priors_origin = "band";  ///< "band", "table1" or the prior file's path (a label for fit.json)
  bool reduce_symmetry = true;
  DataCount data_count = DataCount::two_per_point;
  /// The cheapest order whose passive estimate meets `target` (selection_rule.hpp; docs/method.md, "Accuracy
  /// target", has why this and not the evidence rule is the default).
  SelectionRule rule = SelectionRule::target();
  /// The accuracy the user needs (selection/accuracy_target.hpp): the grid grows only while the selected order's
  /// passive estimate misses it, and the rule `target` ships the cheapest order that meets it.
  AccuracyTarget target{};
  /// The most buffers (Q + 2S) a node may spend (0: no limit): larger orders are neither grown nor selected.
  int max_buffers = 0;
  int threads = 0;  ///< 0 = hardware concurrency
  /// Rounds of re-running orders flagged by missed_mode_warnings, each doubling the order's live points by
  /// runs added and merged with its run (rerun_missed_modes in fit.cpp; a narrow mode with prior-volume
  /// fraction f at the contour where it starts to dominate is found only if n·f ≳ 1, Skilling 2006 §8).
  int missed_mode_retries = 2;
  /// Independent runs an order's first run is made of, each with its share of sampler.live and a seed stream of
  /// its own, merged into one run (inference/run_merge.hpp). With two or more, the error of ln Z comes from their
  /// scatter where it exceeds √(H/n): a slice chain starts from a live point and stays in its mode, so the live
  /// points' share of the modes drifts, which √(H/n) does not see. One by default: at a fixed total of live
  /// points, runs of half as many find fewer modes of real data's larger orders (docs/method.md, "Model selection",
  /// "Independent runs", has the measurements both ways).
  int runs = 1;
  /// Truncate the prior to passive models (Re G(jω) ≥ 0 ∀ω, model/passivity.hpp): ln L = −∞ outside, so
  /// evidence and posterior are those of the prior renormalised to the passive set (NestedRun::
  /// log_support_fraction holds the estimated passive prior fraction).
  bool passive = false;
  /// poles by default: exact in the residues and the noise, calibrated, and seconds per grid
  /// (docs/validation.md); order_sampler turns it into `full` where the priors or `passive` need it.
  SamplerKind sampler_kind = SamplerKind::poles;
  /// How many real poles and how many pairs the grid may gain beyond qmax/smax when the selected order lies
  /// on its edge (selection/grid_growth.hpp; 0 keeps the grid as given).
  int grid_growth = 2;
};

/// fit.json's per-model "sampler" of runs by the pole sampler (inference/poles_sampler.hpp).
inline constexpr const char* kPoleSamplerName = "poles_analytic_residues";

/// What a round of re-runs for a missed mode showed (selection/fit.cpp, rerun_missed_modes): the ln Z of the
/// runs it added, on their own, against the ln Z the order had before. Where the two agree and the point of
/// higher marginal that flagged the order lies at most kMaxGapNats above what the runs reached, that point lies
/// in a region that holds no evidence more live points find (a corner where spare terms cost nothing): ln Z
/// stands, and the fit says so in a note rather than a warning (docs/method.md, "Model selection"). A larger gap
/// stays a warning whatever the re-runs gave: runs that all miss a mode agree with each other too.
struct RerunCheck {
  /// Agreement: within two errors of the difference, or within 1 nat (4.3 dB, under half the default selection
  /// rule's 10 dB margin) where the runs' scatter exceeds their reported errors (docs/validation.md, "Speed").
  static constexpr double kErrors = 2.0, kNats = 1.0;
  /// The largest gap a note explains: about twice the 2.4 nats by which two switched-off spare pairs of the
  /// reference file's Q1S3 rose above its runs' peak (docs/method.md, "Model selection"), and far below the
  /// 22.5 nats of a mode the grey-foam file's Q2S3 misses (docs/validation.md).
  static constexpr double kMaxGapNats = 5.0;
  double log_z_shift = 0.0;  ///< ln Z of the added runs minus the order's ln Z before them
  double error = 0.0;        ///< error of that difference (independent runs)
  int live = 0;              ///< live points of the added runs together
  bool agrees() const { return std::abs(log_z_shift) <= std::max(kErrors * error, kNats); }
};

struct ModelResult {
  Order order;
  NestedRun run;
  int live = 0;  ///< live points of this run (more than the setting if it was re-run)
  double seconds = 0.0;
  std::vector<ParameterSummary> parameters;  ///< folded to the reduced form
  /// Poles of the best sample, residues refitted under Re G ≥ 0 (set by run_fit; what emit uses by default).
  passivity::PassiveEstimate passive{};
  /// "poles_analytic_residues" or "full" (fit.json per model "sampler").
  std::string sampler = "full";
  /// Why the full sampler ran when the pole sampler was asked for (empty otherwise).
  std::string sampler_note{};
  double cpu_seconds = 0.0;  ///< CPU time of the thread that ran it (for benchmarks on a loaded machine; not stored)
  std::optional<RerunCheck> rerun{};  ///< the last round of re-runs for a missed mode, if any
  /// The passive estimate's accuracy against the data and the fit's target (set with `passive`).
  std::optional<OrderAccuracy> accuracy{};
};

/// Posterior predictive band at the data frequencies: 2.5 %, 50 %, 97.5 % quantiles.
struct PredictiveBand {
  Eigen::ArrayXd f_hz;
  Eigen::ArrayXd re_lo, re_median, re_hi;
  Eigen::ArrayXd im_lo, im_median, im_hi;
  Eigen::ArrayXd alpha_lo, alpha_median, alpha_hi;
  int draws = 0;
};

/// How the fitted orders grew beyond Q0-qmax × S0-smax (selection/grid_growth.hpp).
struct GridGrowth {
  int qmax = 0, smax = 0;          ///< the largest Q and S fitted (the grown orders need not fill that rectangle)
  std::vector<std::string> steps;  ///< one line per growth step, in order
  /// Why the selected order still lies on the grid's edge (empty when it lies inside); also a warning.
  std::string edge;
};

struct FitResult {
  std::vector<ModelResult> models;  ///< Q-major: the grid Q0-qmax × S0-smax, then the orders growth added
  std::size_t selected = 0;
  PredictiveBand predictive;        ///< of the selected order
  std::vector<std::string> warnings;  ///< e.g. missed modes (see missed_mode_warnings)
  std::vector<std::string> notes;     ///< missed modes that re-runs showed hold no evidence (missed_mode_notes)
  GridGrowth grid;
};

/// Order (Q', S') contains (Q, S) when Q' ≥ Q and S' ≥ S (zero residues reproduce the smaller
/// model), so its best likelihood can never be lower. When a run's max ln L falls more than
/// `tolerance` nats below that of an order it contains, that run missed the better mode: the
/// evidence of that order is an underestimate. Conversely, when the best θ of an order that contains it,
/// with the surplus terms dropped and the residues refitted (selection/reduced_model.hpp), beats a run's
/// max ln L by more than `tolerance`, that run missed the mode the larger order found.
struct MissedMode {
  std::size_t order;      ///< index into models: the run that missed a mode
  std::size_t contained;  ///< index of the order that shows it (contained in it, or containing it if `larger`)
  double reference_log_l = 0.0;  ///< the ln L that order shows is reachable
  bool larger = false;
  double own_log_l = 0.0;  ///< the missing run's best: its ln L, or its marginal's peak when `marginal`
  /// Compared on the pole sampler's marginal L(ψ) (selection/reduced_model.hpp) rather than on ln L.
  bool marginal = false;
};
/// (Both checks, with the data: selection/missed_modes.hpp.)
/// The check by contained orders alone.
std::vector<MissedMode> missed_modes(const std::vector<ModelResult>& models, double tolerance = 2.0);
/// The readable form of a missed_modes result, one warning per order.
std::vector<std::string> missed_mode_warnings(const std::vector<ModelResult>& models,
                                              const std::vector<MissedMode>& missed);
/// The missed modes that the order's last re-run round explains (RerunCheck: ln Z agreed, the gap at most
/// kMaxGapNats): a point of higher marginal exists, and runs with more live points left ln Z where it was.
/// missed_mode_warnings skips these.
std::vector<std::string> missed_mode_notes(const std::vector<ModelResult>& models, const std::vector<MissedMode>& missed);
/// One warning per order whose independent runs (FitSettings::runs, and the re-runs merged with them) still
/// disagree by more than RerunCheck::kMaxGapNats on the error of ln Z.
std::vector<std::string> runs_disagree_warnings(const std::vector<ModelResult>& models);
/// missed_mode_warnings of the check by contained orders alone.
std::vector<std::string> missed_mode_warnings(const std::vector<ModelResult>& models, double tolerance = 2.0);

/// The sampler an order of this fit runs, chosen here only: `settings.sampler_kind`, except that the
/// uniform residue prior and `passive` fits need the residues sampled (`full`; `note` gets why, when the
/// pole sampler was asked for).
SamplerKind order_sampler(const FitSettings& settings, std::string* note = nullptr);

/// `settings` with the band priors resolved for `data` (PriorRanges::band at its highest angular frequency,
/// the admittance scale kept) when priors.band_of_data; otherwise unchanged. Every entry point that has the
/// data applies it (fit_order, run_first_round, complete_fit, fit_record), so a fit, a library unit and a
/// validation run agree.
FitSettings with_band_priors(FitSettings settings, const Measurement& data);

/// Seed of the run for `order`, derived from the user seed (independent of grid and thread count).
std::uint64_t order_seed(std::uint64_t user_seed, const Order& order);

/// An order as a model of the data (inference/model.hpp): θ packed as model/order.hpp, the uniform priors
/// of `settings` with the symmetry fold (or without, if not reduced), the marginal-Gaussian likelihood,
/// −∞ outside the passive models when `settings.passive`. One instance per thread (the likelihood holds
/// work buffers).
Model order_model(const Measurement& data, const Order& order, const FitSettings& settings);

/// Runs one order: nested sampling plus folded summaries (a fit's first run of it).
ModelResult fit_order(const Measurement& data, const Order& order, const FitSettings& settings,
                      const NestedProgressFn& progress = {});

/// The `n` highest-likelihood samples of a run (folded), best first.
std::vector<Eigen::VectorXd> best_samples(const ModelResult& model, int n);

/// Runs the whole grid, selects, and adds each order's passive estimate (and a warning when the data
/// themselves are not passive at some points). Throws InputError if the data cannot constrain the largest order.
/// run_first_round, then complete_fit: the one definition of a fit, whether its orders run in this process
/// or as separate work units (library/, docs/library.md).
FitResult run_fit(const Measurement& data, const FitSettings& settings, Progress& progress);

/// The first round of a fit: fit_order(data, order, settings, ..., round 0) of every order of the grid, in
/// grid order (order_grid). Each entry depends only on the data, the settings and its order, so it may be
/// computed anywhere (a library work unit is exactly one entry). Throws InputError as run_fit.
std::vector<ModelResult> run_first_round(const Measurement& data, const FitSettings& settings, Progress& progress);

/// The rest of a fit from its first round (`first_round`: one result per order, grid order): the re-runs of
/// orders that missed a mode (they depend on the other orders' results, so they run here), the selection,
/// the growth of the grid while the selected order lies on its edge (the added orders run here too), the
/// passive estimates, the warnings and the predictive band.
FitResult complete_fit(const Measurement& data, const FitSettings& settings, std::vector<ModelResult> first_round,
                       Progress& progress);

/// Predictive band from `draws` equal-weight posterior draws (deterministic given the seed).
PredictiveBand predictive_band(const Measurement& data, const ModelResult& model, int draws, std::uint64_t seed);

}  // namespace admitgen

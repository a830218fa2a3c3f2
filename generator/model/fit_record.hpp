// SPDX-License-Identifier: MIT
/// @file
/// What a fit file holds (docs/formats.md, "fit.json"), as plain data: the record `admitgen fit` writes
/// and `emit`, `check`, `diagnose` and the fit report take. Written from a fit by selection/fit_record.hpp;
/// read from and written to text only by io/fit_file.hpp, which owns the keys and the schema version.
/// Members marked "absent in older fits" are std::optional: fits written by earlier versions of admitgen
/// lack them, and the reader accepts that.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace admitgen {

/// Schema identifier of the fit file.
inline constexpr const char* kFitSchema = "admitgen.fit/1";

/// Posterior summary of one parameter (contract name: G_inf, A_1, lambda_1, ...).
struct FitParameter {
  std::string name;
  double mean = 0.0, std = 0.0, ci95_lo = 0.0, ci95_hi = 0.0, max_likelihood = 0.0;
};

/// The data the fit was made to and how the file was read.
struct FitInput {
  std::string path, sha256;
  std::int64_t points = 0;
  double f_min_hz = 0.0, f_max_hz = 0.0;
  std::string columns;  ///< column spec, or "auto"
  std::string quantity;
  std::optional<std::string> read_as;  ///< absent in older fits
  std::optional<double> rho_c;         ///< null: values were normalised
  std::optional<std::array<double, 2>> band;  ///< null: the whole file
};

/// How fit.json and the report spell the automatic number of slices per replacement
/// (NestedSettings::slices_per_replacement, inference/nested_sampler.hpp).
inline constexpr const char* kAutomaticSlices = "3 + dim";

struct FitSamplerSettings {
  std::string method;
  double dlogz = 0.0;
  std::int64_t max_iterations = 0;
  std::optional<std::int64_t> missed_mode_retries;  ///< absent in older fits
  std::optional<std::int64_t> runs;                 ///< independent runs per order; absent in older fits (one)
  std::optional<std::int64_t> slices;               ///< empty: automatic (kAutomaticSlices)
  std::optional<std::string> residues;              ///< absent in older fits
};

/// The accuracy target of a fit (selection/accuracy_target.hpp); absent in older fits.
struct FitTarget {
  double max_band_delta_alpha = 0.0;
  std::optional<double> max_relative_rms;  ///< absent when not part of the target
  std::optional<std::int64_t> max_buffers;  ///< absent when unlimited
};

struct FitSettingsRecord {
  std::int64_t live = 0;
  std::uint64_t seed = 0;
  std::string priors_source;
  std::optional<std::string> residue_prior;  ///< absent in older fits (then: uniform over the ranges)
  bool symmetry_reduced = false;
  /// Prior range per family, in file order (G_inf, A, lambda, B, C, alpha, beta).
  std::vector<std::pair<std::string, std::array<double, 2>>> prior_ranges;
  std::string likelihood, select;
  std::int64_t qmax = 0, smax = 0;
  FitSamplerSettings sampler;
  std::optional<std::string> passive;  ///< present when the prior was truncated to passive models
  std::optional<std::int64_t> grid_growth;  ///< absent in older fits (their grids never grew)
  std::optional<FitTarget> target;          ///< absent in older fits
};

/// The grid finally fitted, when it grew beyond settings.qmax × settings.smax or the selected order lies on its
/// edge (selection/grid_growth.hpp).
struct FitGrid {
  std::int64_t qmax = 0, smax = 0;
  std::vector<std::string> steps;    ///< one line per growth step
  std::optional<std::string> edge;   ///< why the selected order still lies on the edge; may name settings
};

/// The passive estimate of one order (docs/passivity.md).
struct FitPassiveEstimate {
  std::string poles_from;
  std::int64_t sample_rank = 0;
  std::string residues;
  std::vector<std::pair<std::string, double>> parameters;  ///< name → value, in θ order
  double log_likelihood = 0.0, relative_rms_residual = 0.0, delta_log_likelihood_vs_best_sample = 0.0,
         best_sample_relative_rms_residual = 0.0;
  bool certified_passive = false;
  double min_re_G = 0.0;
  std::int64_t constraint_rounds = 0;
  /// Absent in older fits and when the poles were not searched (docs/passivity.md, "Searching the poles"):
  /// the residual of the best candidate with sampled poles, and the search's Levenberg–Marquardt steps.
  std::optional<double> sampled_poles_relative_rms_residual;
  std::optional<std::int64_t> pole_search_steps;
  /// Why passivity costs more than 1.25× the best sample's residual; absent when it costs less.
  std::optional<std::string> passivity_cost;
  /// With passivity_cost: the relative RMS residual of the best passive fit of any order (docs/passivity.md,
  /// "The passive bound"); absent in older fits.
  std::optional<double> passive_bound_relative_rms_residual;
  /// term_conditioning of the estimate and of the best sample over the data (docs/passivity.md,
  /// "Conditioning"); absent in older fits.
  std::optional<double> conditioning, best_sample_conditioning;
  /// Why an estimate of conditioning above 10 was kept (the trade-off against the residual); absent otherwise.
  std::optional<std::string> conditioning_tradeoff;
};

/// What an order costs and how close its passive estimate comes (selection/accuracy_target.hpp); absent in older
/// fits.
struct FitAccuracy {
  std::int64_t buffers = 0;  ///< Q + 2S state buffers per node
  double relative_rms_residual = 0.0, max_band_delta_alpha = 0.0, worst_band_hz = 0.0;
  bool meets_target = false;
  double conditioning = 1.0;  ///< of the passive estimate (passive_estimate.conditioning, docs/passivity.md)
};

struct FitGoodness {
  std::string estimate;
  double relative_rms_residual = 0.0, max_abs_delta_alpha = 0.0;
};

/// One fitted order.
struct FitModel {
  std::string order;
  std::int64_t q = 0, s = 0;
  std::optional<std::int64_t> live;  ///< absent in older fits (then: the settings' live)
  double log_evidence = 0.0, log_evidence_error = 0.0, max_log_likelihood = 0.0, information_nats = 0.0;
  std::int64_t likelihood_calls = 0, iterations = 0;
  std::string stopped_by;
  std::optional<double> seconds;  ///< run time; only in fits of earlier versions (now left out: equal runs, equal bytes)
  std::vector<FitParameter> parameters;
  std::optional<FitPassiveEstimate> passive_estimate;  ///< absent in older fits
  std::optional<double> log_passive_prior_fraction;    ///< with --passive
  std::optional<FitGoodness> goodness_of_fit;          ///< absent in older fits
  std::optional<FitAccuracy> accuracy;                 ///< of the passive estimate; absent in older fits
  std::optional<std::string> sampler;                  ///< absent in older fits
  std::optional<std::string> sampler_note;  ///< may name settings (core/errors.hpp, setting())
};

/// Median and 95 % band of the selected order's model curve over its posterior (fit.json's "predictive"; the
/// noise is not added, docs/formats.md).
struct FitPredictive {
  std::int64_t draws = 0;
  std::vector<double> quantiles;  ///< 0.025, 0.5, 0.975
  std::vector<double> f_hz;
  /// One row per quantile, each as long as f_hz.
  std::array<std::vector<double>, 3> re_G, im_G, alpha;
};

struct FitRecord {
  std::string schema = kFitSchema;
  std::string version;
  FitInput input;
  FitSettingsRecord settings;
  std::vector<FitModel> models;
  std::vector<std::pair<std::string, double>> bayes_factors_deciban, bayes_factor_errors_deciban;  ///< by order
  std::string selected_order, selected_rule;
  std::vector<FitParameter> parameters;        ///< the selected order's
  /// What each model's log_evidence_error is (e.g. a lower bound of the seed scatter); absent in older fits.
  std::optional<std::string> log_evidence_error_meaning;
  std::optional<FitPredictive> predictive;     ///< absent in older fits
  /// Absent in older fits. Texts may name settings (core/errors.hpp, setting()): writers of files and
  /// reports give them plain_settings(), the command line spells each as its flag.
  std::optional<std::vector<std::string>> warnings;
  /// Findings that change no result (e.g. a missed mode that re-runs showed holds no evidence); absent when
  /// there is none, and in older fits.
  std::optional<std::vector<std::string>> notes;
  std::optional<std::string> posterior;        ///< file name of the posterior index, when written
  std::optional<FitGrid> grid;                 ///< absent when the grid did not grow and the selection is inside it

  /// The "models" entry of `order` (empty: the selected order), compared as parsed orders (Order::parse,
  /// which throws InputError for text that is not one); nullptr when that order was not fitted.
  const FitModel* model(const std::string& order = {}) const;
};

}  // namespace admitgen

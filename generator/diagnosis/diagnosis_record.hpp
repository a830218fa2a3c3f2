// SPDX-License-Identifier: MIT
/// @file
/// What a diagnosis file holds (docs/formats.md, "diagnosis.json"), as plain data: the record `admitgen
/// diagnose` writes and its report (report/diagnosis_report.hpp) takes. Built from a diagnosis by
/// diagnosis_record(); read from and written to text only by io/diagnosis_file.hpp, which owns the keys and
/// the schema version. "parameters" of an effect holds posterior means (and the fixed values).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace admitgen::diagnosis {

struct Diagnosis;

/// Schema identifier of the diagnosis file.
inline constexpr const char* kDiagnosisSchema = "admitgen.diagnosis/3";
/// The schema before shares, main cause and dropped members; still read (io/diagnosis_file.hpp).
inline constexpr const char* kDiagnosisSchemaV2 = "admitgen.diagnosis/2";
/// The schema before combined explanations; still read (io/diagnosis_file.hpp).
inline constexpr const char* kDiagnosisSchemaV1 = "admitgen.diagnosis/1";

struct BandEdges {
  double f_lo = 0.0, f_hi = 0.0, f_center = 0.0;
};

struct BandGapRecord {
  BandEdges band;
  std::int64_t points = 0;
  double gap = 0.0, gap_re = 0.0, gap_im = 0.0, delta_alpha_max = 0.0;
};

struct WhitenessRecord {
  std::string test;
  double lag1 = 0.0, z = 0.0;
  bool white = false;
};

struct GapRecord {
  std::string metric;
  double total = 0.0, total_re = 0.0, total_im = 0.0, delta_alpha_max = 0.0;
  WhitenessRecord whiteness;
  std::vector<BandGapRecord> bands;
  BandEdges worst_band;
  double worst_band_gap = 0.0;
};

struct StageRecord {
  std::string stage;  ///< fit | discretization | quantization | simulation
  double gap = 0.0;
  std::vector<BandGapRecord> bands;
  BandEdges worst_band;
  double cumulative_gap = 0.0;
  std::vector<BandGapRecord> cumulative_bands;
  std::optional<std::string> detail;
};

struct EffectParameterRecord {
  std::string name;
  double mean = 0.0, std = 0.0, ci95_lo = 0.0, ci95_hi = 0.0, max_likelihood = 0.0;
  std::string prior;
};

struct EffectRecord {
  std::string effect;
  std::vector<std::pair<std::string, double>> parameters;  ///< posterior means, then the fixed values
  std::vector<EffectParameterRecord> parameter_summary;
  std::vector<std::pair<std::string, double>> fixed_parameters;
  double log_bayes_factor_deciban = 0.0, log_evidence = 0.0, log_evidence_error = 0.0, max_log_likelihood = 0.0;
  std::int64_t likelihood_calls = 0;
  double gap_after = 0.0, shrink = 1.0, explained_fraction = 0.0;
  BandEdges band;
  std::vector<BandGapRecord> bands_after;
  WhitenessRecord whiteness_after;
  /// How the evidence was computed ("nested sampling" or "quadrature") and whether the sampling stopped
  /// early under the budget (docs/method.md); absent in diagnoses written before both existed.
  std::optional<std::string> evidence_method;
  std::optional<bool> stopped_early;
};

/// One member of the verdict's explanation.
struct ExplanationMemberRecord {
  std::string effect;
  std::vector<std::pair<std::string, double>> parameters;  ///< material: exactly its one ratio
  double log_bayes_factor_deciban = 0.0;                   ///< against the explanation without it
  double shrink_added = 1.0;
};

/// A member's share of the squared gap (docs/diagnosis.md, "Main cause").
struct ShareRecord {
  std::string effect;
  std::int64_t member = 0;  ///< index into the explanation
  double share = 0.0;
};

/// A member the backward step dropped: within the decision margin, the explanation with fewer parameters.
struct DroppedMemberRecord {
  std::string effect;
  std::optional<std::string> parameter;  ///< material only: the catalogue parameter
  double log_bayes_factor_deciban = 0.0;  ///< the explanation with it against the one without it
  std::string reason;
};

/// A member's parameter whose posterior presses on a bound of its prior (prior_bound.hpp).
struct PriorBoundRecord {
  std::string effect, parameter;
  std::string bound;  ///< "lower" or "upper"
  double bound_value = 0.0, mean = 0.0;
  std::string fix;
};

struct VerdictRecord {
  std::string effect = "none";  ///< the primary effect, none or unexplained
  std::vector<ExplanationMemberRecord> explanation;
  std::vector<ShareRecord> shares;        ///< largest first; empty in /1 and /2 files
  std::optional<ShareRecord> main_cause;  ///< the largest share when it is at least one half
  std::vector<DroppedMemberRecord> dropped;
  /// Present only when a parameter presses on its prior's bound (a key added within schema /3: older
  /// files and diagnoses without such a parameter lack it).
  std::optional<std::vector<PriorBoundRecord>> at_prior_bound;
  double shrink = 1.0, explained_fraction = 0.0;  ///< of the whole explanation
  BandEdges band;
  double log_bayes_factor_deciban = 0.0;
  std::optional<double> margin_deciban;  ///< none: no runner-up
  bool residual_white_after = false;
  std::string rule;
};

/// The prior of one parameter of a tried effect: a description, or a fixed value.
struct EffectPriorRecord {
  std::string name;
  std::optional<std::string> description;
  std::optional<double> fixed;
};

struct DiagnosisSettingsRecord {
  std::int64_t live = 0;
  double dlogz = 0.0;
  std::uint64_t seed = 0;
  std::optional<std::string> evidence;  ///< how each candidate's evidence is computed; absent in older files
  std::string likelihood, decision_rule;
  std::vector<std::pair<std::string, std::vector<EffectPriorRecord>>> priors;  ///< by effect
};

struct DiagnosisInputRecord {
  std::string real_path, real_sha256, sim;
  std::int64_t points = 0;
  double f_min_hz = 0.0, f_max_hz = 0.0, level_rms_y = 0.0;
  std::vector<std::string> warnings;  ///< may name settings (core/errors.hpp, setting())
};

struct DiagnosisRecord {
  std::string schema = kDiagnosisSchema;
  std::string version;
  DiagnosisInputRecord input;
  DiagnosisSettingsRecord settings;
  GapRecord gap;
  std::vector<StageRecord> stages;
  double log_evidence_none = 0.0;
  std::vector<EffectRecord> effects;  ///< best first
  VerdictRecord verdict;
};

/// The record of a diagnosis, stamped with this version of admitgen.
DiagnosisRecord diagnosis_record(const Diagnosis& diagnosis);

}  // namespace admitgen::diagnosis

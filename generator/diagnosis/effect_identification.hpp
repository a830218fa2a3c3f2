// SPDX-License-Identifier: MIT
/// @file
/// Which unmodelled effect explains the gap: for every candidate e (effect_candidates.hpp) the
/// evidence Z_e = ∫ L(ϑ) π(ϑ) dϑ of "simulated side + e" is computed and compared with the no-effect
/// model, whose evidence is its likelihood (no free parameter):  BF_e = 10 log₁₀(Z_e/Z₀) deciban
/// (inference/evidence.hpp). The prior volume of ϑ makes the comparison fair between effects with 0 to 3
/// parameters (Occam factor), so a flexible effect that only fits noise loses against none.
///
/// Each candidate is a model (inference/model.hpp) of the measurement. How its evidence is computed
/// (docs/method.md, "Comparing effects"):
///  * 0 parameters: Z = L at the one point ("closed_form");
///  * 1 parameter: quadrature over the prior (inference/quadrature_evidence.hpp, "quadrature"), exact to
///    about 1e-6 nats, where nested sampling would carry ±√(H/n) ≈ 0.4 nat;
///  * 2-3 parameters: nested sampling (inference/nested_sampler.hpp, "nested_sampling"), candidate i on
///    the seed stream derive_seed(seed, i).
/// Candidates run in parallel (core/parallel.hpp); each writes only its own result, so the results do
/// not depend on the thread count. The quadrature candidates run first; the best evidence among them and
/// no effect is then the leader, fixed before any sampled candidate starts. A sampled candidate stops
/// early when it cannot come near that leader (early_stop_bound below); its evidence is then the
/// estimate at the stop, and diagnosis.json marks it.
///
/// Each effect then reports its posterior (mean, std, 95 % interval, max-likelihood value) and the gap
/// left at the max-likelihood ϑ: gap_after, shrink = gap_before/gap_after over the whole data, and the
/// band-resolved gap after.
#pragma once

#include "diagnosis/effect_candidates.hpp"
#include "diagnosis/effect_likelihood.hpp"
#include "diagnosis/gap_metrics.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/posterior.hpp"
#include "inference/quadrature_evidence.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace admitgen {
class Progress;  // core/progress.hpp
}  // namespace admitgen

namespace admitgen::diagnosis {

/// Odds of at least 100 : 1 ("decisive" on Jeffreys' scale): what an effect must gain to be named
/// (verdict.hpp) and to join an explanation (explanation.hpp).
inline constexpr double kDecisiveDeciban = 20.0;

/// A sampled candidate whose bound stays this far below the leader's evidence stops early (5× the
/// decision threshold of verdict.hpp: such a candidate can neither win nor be the runner-up that
/// decides the margin).
inline constexpr double kEarlyStopDeciban = 100.0;

/// A reference density's standard deviation, in units of the earlier posterior's (its 95 % interval over
/// 3.92): information ln 4 − 15/32 ≈ 0.9 nat per parameter when the posterior sits where it sat before,
/// against the several nats of compressing it from its prior.
inline constexpr double kReferenceWidening = 4.0;
/// Uniform shares: from a posterior of the same model (a screening run) or of the same member in the
/// explanation, and from a member's single-effect posterior (which may sit elsewhere once the other
/// members take their share of the gap).
inline constexpr double kReferenceShareJoint = 0.1;
inline constexpr double kReferenceShareSingle = 0.5;

/// A screened joint candidate this far below the best and below decisive is not run in full
/// (evaluate_contenders): 5 standard errors of a screening run's ln Z.
inline constexpr double kScreenDeciban = 20.0;

struct IdentificationSettings {
  /// Effects have 0-3 parameters on a fixed simulated admittance, so a hundred live points already give
  /// ln Z to ±√(H/n) ≈ 0.4 nat (2 dB), far inside the 20 dB decision margin. seed is the user seed.
  NestedSettings sampler = effect_sampler();
  QuadratureSettings quadrature{};
  bool use_quadrature = true;  ///< false: 1-parameter candidates are sampled too (the former method)
  int threads = 0;  ///< candidates run in parallel on this many threads; 0 = all cores
  double early_stop_deciban = kEarlyStopDeciban;  ///< 0: never stop early
  /// Live points of the screening runs of the combined search (evaluate_contenders); ≥ sampler.live:
  /// no screening. A quarter of the default.
  int screen_live = 25;
  /// Passes of the swap step of the combined search (explanation.hpp): after a kept swap it repeats over
  /// every member, at most this many passes in all. 1: the first pass only (earlier members only), the
  /// search before repeated swaps (a test uses it to reach the backward step on a known path).
  int swap_passes = 3;
  /// Pair exchanges of the combined search at most (explanation.hpp): after the additions end with the
  /// residual structured, two members are taken out and regrown. 0: none, the search before them.
  int pair_exchanges = 2;

  static NestedSettings effect_sampler() {
    NestedSettings s;
    s.live = 100;
    s.dlogz = 0.1;
    return s;
  }
};

struct EffectResult {
  std::string name;
  std::size_t candidate = 0;  ///< index into the candidates it was evaluated from
  std::vector<ParameterPrior> priors;
  std::vector<ParameterSummary> parameters;           ///< one per prior, in its order
  std::vector<std::pair<std::string, double>> fixed;  ///< parameters held fixed
  std::string method;                                 ///< closed_form | quadrature | nested_sampling
  double log_z = 0.0;
  double log_z_error = 0.0;
  double max_log_likelihood = 0.0;
  double bayes_factor_deciban = 0.0;  ///< against no effect
  long calls = 0;
  bool stopped_early = false;
  double log_z_bound = 0.0;  ///< when stopped early: the bound that stopped it (early_stop_bound)
  double seconds = 0.0;      ///< wall time of this candidate (not written to diagnosis.json)
  double cpu_seconds = 0.0;  ///< CPU time of its thread (the wall time on an idle core; not written either)
  std::vector<double> best;  ///< the max-likelihood ϑ
  Gap gap_after;
  double shrink = 1.0;         ///< gap_before.total / gap_after.total
  double explained = 0.0;      ///< fraction of the squared gap explained: 1 − 1/shrink²
  std::size_t band = 0;        ///< index of the band this effect explains most (gap_metrics most_improved_band)
};

struct Identification {
  double log_z_none = 0.0;
  std::vector<EffectResult> effects;  ///< best (largest Bayes factor) first; ties keep the candidate order
};

/// The bound a sampled candidate is held to after its live points have shrunk to X ≤ 1/n² of the
/// prior: 2 ln L_max,live − ln L* (the best live likelihood plus the live points' spread above the
/// contour L*). Z ≤ max L, and for a peak the best of n live points falls short of max L by far less
/// than the spread (docs/method.md, "Early stop"). X ≤ 1/n² first: a mode of prior mass below that would
/// not have been found by the rest of the run either (n·mass ≪ 1).
double early_stop_bound(const NestedStatus& status);
bool early_stop_allowed(const NestedStatus& status, int live);

/// A candidate as a model of the measurement (inference/model.hpp): its priors through the unit cube, the
/// likelihood of its prediction. Holds references to both.
/// With a reference density (EffectCandidate::reference) the cube is q's and the likelihood L/q: the
/// same evidence (diagnosis/reference_prior.hpp).
Model effect_model(const EffectCandidate& candidate, const EffectLikelihood& likelihood);

/// ln q(u(θ)) of the candidate's reference densities (0 without).
double reference_log_density(const EffectCandidate& candidate, const double* theta);

/// Reference densities from an earlier posterior of the same parameters (docs/method.md, "Reference
/// priors in the combined search"): each 95 % interval mapped to u, widened kReferenceWidening× with a
/// uniform share; a parameter without a summary (posterior.size() ≠ priors.size()) keeps its prior.
std::vector<ReferenceDensity> reference_densities(const std::vector<ParameterPrior>& priors,
                                                  const std::vector<ParameterSummary>& posterior, double uniform_share);

/// How the evidences are computed and the early-stop rule, in words (diagnosis.json "settings").
std::string describe_evidence_methods(const IdentificationSettings& settings);

/// The evidence of each candidate as described above, with the runs in parallel; `first_stream` offsets
/// the seed streams (candidate i samples with derive_seed(settings.sampler.seed, first_stream + i)), so
/// a later search over combinations can call this again with fresh streams. `log_z_floor` is a leader
/// known before the call (e.g. no effect's ln Z). Fills everything but the gap fields and the Bayes factor.
std::vector<EffectResult> evaluate_candidates(const std::vector<EffectCandidate>& candidates,
                                              const EffectLikelihood& likelihood, const IdentificationSettings& settings,
                                              double log_z_floor, std::uint64_t first_stream, Progress& progress);

/// A round of the combined search needs one answer: which candidate has the largest evidence, and whether
/// it beats `log_z_reference` (the explanation without it) by kDecisiveDeciban. Every candidate is first
/// screened by a run with settings.screen_live live points (a quarter of the cost; ln Z to about
/// √(H/live) ≈ 1 nat, 4 dB); those whose screened evidence is within kScreenDeciban of the larger of
/// the best screened evidence and log_z_reference + kDecisiveDeciban are then run as evaluate_candidates
/// runs them, on the same seed streams, and their results replace the screened ones (method
/// "nested_sampling"; the others keep method "screened"). A candidate left screened is more than 20 dB
/// (5 standard errors of the screening) below the best and below decisive, so it could neither be
/// picked nor make the pick decisive. A contender's full run samples from reference densities built on
/// its screening run's posterior (reference_densities, kReferenceShareJoint). A lone candidate is screened
/// too: a white residual's noise round, one swap, one model of a backward step, which in full would run
/// with every other worker idle. Full runs may start before the screening ends (effect_identification.cpp,
/// EarlyFullRuns), with the same results. With screen_live ≥ live every candidate runs in full.
std::vector<EffectResult> evaluate_contenders(const std::vector<EffectCandidate>& candidates,
                                              const EffectLikelihood& likelihood, const IdentificationSettings& settings,
                                              double log_z_reference, std::uint64_t first_stream, Progress& progress);

/// Fills r's gap fields (gap_after at the max-likelihood ϑ, shrink, explained, band) for `candidate`.
void fill_gap(EffectResult& r, const EffectCandidate& candidate, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
              const Gap& gap_before);

/// Runs every candidate against y_real (at f_hz, level ‖y_real‖) and ranks them; y_sim is the
/// no-effect model.
Identification identify_effects(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
                                const Eigen::ArrayXcd& y_sim, const Gap& gap_before,
                                const std::vector<EffectCandidate>& candidates, const IdentificationSettings& settings,
                                Progress& progress);

}  // namespace admitgen::diagnosis

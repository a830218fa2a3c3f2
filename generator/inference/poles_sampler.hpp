// SPDX-License-Identifier: MIT
/// @file
/// Nested sampling over the poles only, the residues integrated out analytically
/// (inference/residue_marginal.hpp; docs/method.md, "Sampling the poles only"), then the complete
/// posterior: for every pole sample, residues drawn from their conditional truncated Student t, so the
/// returned run looks like a full-θ run (same packing, same weights semantics) to summaries, predictive
/// bands, reports and emit.
#pragma once

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/priors.hpp"
#include "model/order.hpp"

namespace admitgen {

/// How the pole sampler accounts for the residue box (docs/method.md, "Truncation by the residue box").
enum class BoxMassMethod {
  /// The sampled likelihood carries the bound P̃ of the box mass; after the run each point is reweighted by
  /// P̂/P̃ (PolesRun::truncation_correction). Cheap, but the reweighting loses effective samples where P̃
  /// and P_box differ by factors that vary over the posterior.
  reweighted,
  /// The box mass is integrated by the sampler itself: the χ²_ν scale W and p GHK uniforms join ψ as
  /// coordinates (dimension Q + 2S + 1 + p), ln L_ext = ln L_untruncated(ψ) + ln(GHK replicate), whose
  /// integral over those coordinates is L(ψ) exactly. No correction, no bound; each point's residues are
  /// the replicate's own draw of the truncated t.
  sampled,
};

struct PolesRun {
  /// Full θ per point (model/order.hpp packing), weights of the pole run. log_likelihood holds the full
  /// ln L(θ) of each stored θ. One extra point of zero weight (log_weight = −∞) ends the run: the poles
  /// of the highest profile likelihood with their least-squares residues r̂ (inside the box), so
  /// max_likelihood_index finds the best θ the run saw. calls, iterations, information, log_z and its
  /// error are those of the pole run (ln Z includes truncation_correction).
  NestedRun run;
  /// Box correction (docs/method.md, "Truncation by the residue box"). The sampled likelihood uses P̃ (ResidueConditional::
  /// log_p_sampled) for the box mass P_box; every point whose bounds differ (1 − P_lo/P_up > 1e-9) gets the
  /// unbiased estimate P̂, the mean of m GHK replicates (see kBoxDrawBudget), and its
  /// weight is multiplied by ρ = P̂/P̃. ln Z gains ln Σ p_i ρ_i (this field), with the Monte Carlo error below
  /// (added in quadrature to run.log_z_error); elsewhere ρ = 1 exactly (to 1e-9).
  double truncation_correction = 0.0;
  double truncation_correction_error = 0.0;
  /// Kish effective sample size after / before the reweighting (1 when nothing was reweighted).
  double reweighted_ess_ratio = 1.0;
  /// Posterior weight of the points whose residues came from the Gibbs fallback of draw_residues.
  double gibbs_weight = 0.0;
  BoxMassMethod box_mass = BoxMassMethod::reweighted;
};

/// Runs the pole sampler for `order`. With no poles (Q0S0) the evidence is the closed form itself
/// (stopped_by "analytic", error 0) and `settings.live` equal-weight draws of r form the posterior.
/// `draw_seed` seeds the residue draws (BoxMassMethod::reweighted; the sampled method needs none).
PolesRun run_poles_sampler(const Measurement& data, const Order& order, const PriorRanges& priors,
                           bool reduce_symmetry, DataCount count, const NestedSettings& settings,
                           std::uint64_t draw_seed, const NestedProgressFn& progress = {},
                           BoxMassMethod box_mass = BoxMassMethod::reweighted);

/// GHK replicates for the box-mass estimates P̂ of one run (inference/residue_draws.hpp): kBoxDrawsPerPoint
/// per point that needs one, at most kBoxDrawBudget in all, shared over the points in proportion to their
/// weight p_i, at least kMinBoxDraws and at most kMaxBoxDraws per point. The reported correction error
/// (from the replicates' sample variances) says what was reached.
constexpr double kBoxDrawBudget = 2e5;
/// Points of a run whose posterior share is below this over the number of points keep their least-squares
/// residues (clamped to the box) instead of a draw from the conditional (together at most this share).
constexpr double kNegligibleShare = 1e-6;
constexpr double kBoxDrawsPerPoint = 20.0;
constexpr long kMinBoxDraws = 2;  ///< the sample variance needs two
constexpr long kMaxBoxDraws = 20000;

}  // namespace admitgen

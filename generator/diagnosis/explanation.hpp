// SPDX-License-Identifier: MIT
/// @file
/// Combined explanations (docs/diagnosis.md, "Combined explanations"): real gaps are rarely one effect.
/// After the single effects (effect_identification.hpp), a greedy forward selection by evidence:
///
///   E₁ = the single effect with the largest evidence, if BF(E₁ : none) ≥ 20 dB (else no explanation);
///   round r: for every candidate e not in E_r, the evidence of E_r + e with all its parameters free
///   (fitted jointly, combine_effects); the best is accepted if BF(E_r + e : E_r) ≥ 20 dB;
///   stop when no addition is decisive, when the residual of E_r is white (residual_whiteness.hpp), or at
///   kMaxExplanationEffects members. A white residual has no structure left in its mean, but a noise
///   shape (heteroscedastic_noise) does not show in the lag-1 test: with a white residual the round
///   still tries the noise-stage effects, and only them.
///   swap step: after an addition that leaves the residual structured, every earlier member in turn is
///   replaced by every candidate not in the explanation (all refitted jointly); the best swap is kept if
///   it is decisive (≥ 20 dB) against the explanation as it stands. It undoes a first member that
///   mimics two true ones, which pure addition cannot. Once a swap is kept and the residual is still
///   structured, the step repeats over every member, the last added included (it was chosen given
///   earlier members that have changed since), at most IdentificationSettings::swap_passes (3) passes.
///   The members kept in a swap sample from the explanation's posterior with a single effect's uniform
///   share (they may move far once the member swapped in takes over part of their work).
///   mimic swap: after an addition that leaves the residual white, every earlier member in turn is
///   replaced by its kMimicsPerMember closest mimics (the candidates whose single-effect correction
///   ŷ − y_sim is most nearly parallel to its own); the best is kept if it is decisive. A white
///   explanation can still hold a mimic with another member making up the difference.
///   backward step: after every addition (and its swap), each member is tested against the explanation
///   without it by the rule of an addition, BF(E : E − m) ≥ 20 dB. The weakest member that is not
///   decisive is dropped (the two explanations are within the decision margin: the one with fewer
///   parameters is kept), and the step repeats. A dropped member is not offered again, so the search
///   cannot cycle; it ends at the latest after kMaxExplanationRounds rounds. The explanations without one
///   member are screened; one without a member that rides beside a partner (a mimic: their single-effect
///   corrections alike, kPartnerLikeness) is run in full, white residual or not: the partner must move
///   far to take over the member's part, which a screening run can miss.
///   pair exchange: when the additions end with the residual structured and three or more members, every
///   pair of members is taken out together and the rest regrown by two greedy additions (the
///   kThirdsPerPair best thirds, every fourth beside each), screened without early stop; the best is
///   kept when it is decisive, followed by a swap pass while structured, the backward step and further
///   additions; at most IdentificationSettings::pair_exchanges (2) times. It reaches a truth two members away, which no single swap
///   does.
///
/// Each effect enters at most once (each catalogue parameter of `material` counts as its own effect).
/// The evidence of a joint model pays the Occam factor of every added parameter, so an addition that
/// only fits noise is not decisive. Every joint candidate samples from reference densities on its prior
/// built on earlier posteriors (its members' in the explanation, the added member's single-effect one),
/// the likelihood divided by them: the same evidence in fewer calls (docs/method.md, "Reference priors in
/// the combined search"). Seed streams: the single effects sample on 0 … n − 1 (n candidates); every
/// later batch of joint candidates (an addition round, its swaps, restated steps, the models of a
/// backward step) takes the next block of streams, one per model, in the order the search runs them, so
/// the search is deterministic whatever the thread count.
///
/// Shares (docs/diagnosis.md, "Main cause"): the part of the squared gap each member explains, at the
/// joint max-likelihood parameters. With G(S) = Σ|y_real − ŷ_S|² for the members S acting alone
/// (composed as combine_effects composes them) and v(S) = G(∅) − G(S), member k's share is its Shapley
/// value  φ_k = Σ_{S ⊆ M∖k} |S|! (m − |S| − 1)! / m! · (v(S ∪ k) − v(S)),  divided by G(∅): the shares
/// add up to the explained fraction of the whole explanation and do not depend on the members' order.
/// Beside it, what member k explains alone at the same parameters, v({k})/G(∅): where members partly cancel, a
/// Shapley share can exceed 1 while the member alone explains little or makes the gap worse.
#pragma once

#include "diagnosis/effect_identification.hpp"

#include <cstddef>
#include <vector>

namespace admitgen::diagnosis {

/// Members at most (bounds the search's cost; a gap that needs more is reported as it stands).
inline constexpr std::size_t kMaxExplanationEffects = 4;
/// Mimics tried per earlier member in the mimic swap after a white residual (explanation.cpp mimic_swap).
inline constexpr std::size_t kMimicsPerMember = 1;
/// A member rides beside a partner when their single-effect corrections ŷ − y_sim have |cos| at least this
/// (explanation.cpp Search::beside_partner): the backward step then runs the explanation without it in full.
inline constexpr double kPartnerLikeness = 0.5;
/// Thirds regrown per pair taken out, the best by screened evidence (explanation.cpp pair_exchange).
inline constexpr std::size_t kThirdsPerPair = 3;
/// Addition rounds at most: each round adds one member, the backward step may take members out again.
inline constexpr std::size_t kMaxExplanationRounds = 2 * kMaxExplanationEffects;
/// A member whose share of the squared gap is at least this, and which alone explains at least this
/// fraction of it, is the main cause (verdict.hpp).
inline constexpr double kMainCauseShare = 0.5;

/// Each member's share of the squared gap (the Shapley value above over G(∅)) and the fraction it explains
/// alone (v({k})/G(∅)), in the members' order.
struct MemberShares {
  std::vector<double> shapley;
  std::vector<double> alone;
};

struct ExplanationStep {
  std::size_t candidate = 0;          ///< index into the candidates
  /// Of the first k + 1 members against the first k (this member is the k-th, from 0), each fitted jointly.
  double bayes_factor_deciban = 0.0;
  double shrink_added = 1.0;  ///< gap of the first k members / gap of the first k + 1
};

/// A member the backward step took out: the explanation with it was not decisively better than the one
/// without it, so the one with fewer parameters was kept.
struct DroppedMember {
  std::size_t candidate = 0;          ///< index into the candidates
  double bayes_factor_deciban = 0.0;  ///< the explanation with it against the one without it (< kDecisiveDeciban)
  std::size_t round = 0;              ///< the addition round after which it was dropped (1 …)
};

struct Explanation {
  std::vector<ExplanationStep> steps;  ///< in the order accepted; empty when no single effect is decisive
  /// Each step's share of the squared gap and what it explains alone (above), in step order; empty with the steps.
  MemberShares shares;
  std::vector<DroppedMember> dropped;  ///< in the order dropped
  /// The accepted members fitted jointly; priors and parameters concatenated in step order (gap fields
  /// and Bayes factor against no effect filled). Meaningless when steps is empty.
  EffectResult joint;
  /// Every joint candidate each round evaluated, in candidate order (costs for benchmarks; not written).
  std::vector<std::vector<EffectResult>> rounds;
  /// The parameter summaries of member k: joint.parameters[offset(k) …].
  std::vector<ParameterSummary> member_parameters(std::size_t k, const std::vector<EffectCandidate>& candidates) const;
};

/// The search above, from the single effects of identify_effects (same candidates, f_hz, y_real and y_sim,
/// the simulated side at f_hz).
Explanation explain(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real, const Eigen::ArrayXcd& y_sim,
                    const Gap& gap_before, const std::vector<EffectCandidate>& candidates,
                    const Identification& identification, const IdentificationSettings& settings, Progress& progress);

/// The shares above of `members` (candidate indices) at the parameters theta (concatenated in the
/// members' order), against y_real; y_sim is the prediction of no member. One per member, in its order.
MemberShares member_shares(const std::vector<EffectCandidate>& candidates, const std::vector<std::size_t>& members,
                                  const std::vector<double>& theta, const Eigen::ArrayXcd& y_real,
                                  const Eigen::ArrayXcd& y_sim);

}  // namespace admitgen::diagnosis

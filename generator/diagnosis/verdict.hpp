// SPDX-License-Identifier: MIT
/// @file
/// The decision rule of `diagnose`, stated once:
///
///   Let e* be the effect with the largest Bayes factor BF against no effect (effect_identification).
///   If BF(e*) < 20 deciban (odds 100 : 1, "decisive" on Jeffreys' scale) the verdict is `none` when
///   the gap's own residual is white, and `unexplained` with an empty explanation when it is structured
///   (a real gap that no effect of the vocabulary moves at all).
///   Otherwise the explanation E grown from e* (explanation.hpp) is the verdict's explanation, and
///   the verdict is `unexplained` when E leaves the residual structured (the lag-1 test of
///   residual_whiteness.hpp fails, |z| ≥ 3); else it is e* (the primary effect, E's first member).
///
/// Why whiteness and not a threshold on the explained fraction: in the validation suite
/// (docs/diagnosis.md, "Validation") three vocabulary effects fitted jointly explain more than 99 % of
/// the squared gap of an out-of-vocabulary case, because a large structured gap is easy to reduce by
/// flexible effects, yet they leave structure (z ≫ 3); the in-vocabulary cases named correctly end
/// white. For `unexplained` the explanation lists the best attempt, and shrink and explained_fraction
/// say how much of the gap it accounts for.
///
/// The band of the verdict is the band e* explains most (largest drop of g_b²); for `none` it is the
/// worst band of the gap. shrink = gap before / gap after over the whole data (1 with no explanation).
/// Decisive support does not mean the effect is the whole story: on real data the residual is rarely
/// white, so an effect can be decisively better than none and still explain little; `explained` and
/// `white_after` say how much is left.
/// Main cause (docs/diagnosis.md, "Main cause"): the members are listed by their share of the squared
/// gap (explanation.hpp member_shares), largest first; the member whose share is at least kMainCauseShare,
/// and which alone explains at least that fraction of the squared gap, is the main cause, named also when the verdict is unexplained ("main cause X (share), structure
/// left"): most of the gap is that effect even though something outside the vocabulary is left.
/// A member's parameter whose posterior presses on a bound of its prior is listed with the fix
/// (prior_bound.hpp).
/// Members the backward step of the search dropped are listed with their Bayes factor (the explanation
/// with them was within the decision margin of the one without, which has fewer parameters).
/// The runner-up's margin is reported as well: two effects within a few deciban of each other are
/// near-degenerate on these data (e.g. reference_plane and temperature both give a phase error ∝ f),
/// which the report then says.
#pragma once

#include "diagnosis/effect_identification.hpp"
#include "diagnosis/explanation.hpp"
#include "diagnosis/gap_metrics.hpp"
#include "diagnosis/prior_bound.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace admitgen::diagnosis {

/// One member of the verdict's explanation.
struct VerdictMember {
  std::string effect;                                      ///< documented name ("material" for a catalogue parameter)
  std::vector<std::pair<std::string, double>> parameters;  ///< posterior means of the joint fit, then fixed values
  double bayes_factor_deciban = 0.0;                       ///< the members up to it against those before it
  double shrink_added = 1.0;                               ///< gap of those before it / gap with it
};

/// One member's share of the squared gap.
struct VerdictShare {
  std::size_t member = 0;  ///< index into Verdict::explanation
  double share = 0.0;      ///< of the squared gap before (the shares add up to `explained`)
};

/// A member the backward step dropped.
struct VerdictDropped {
  std::string effect;
  std::string parameter;              ///< the catalogue parameter of a material member ("" otherwise)
  double bayes_factor_deciban = 0.0;  ///< the explanation with it against the one without it (< 20)
};

struct Verdict {
  std::string effect = "none";  ///< e*, none or unexplained
  std::vector<VerdictMember> explanation;
  std::vector<VerdictShare> shares;  ///< one per member, largest share first (ties: explanation order)
  std::optional<VerdictShare> main_cause;  ///< the first of shares when it and its member alone reach kMainCauseShare
  std::vector<VerdictDropped> dropped;
  std::vector<PriorBoundHit> at_prior_bound;  ///< members' parameters held by a prior bound (prior_bound.hpp)
  double bayes_factor_deciban = 0.0;  ///< of e* (also when the verdict is none)
  double margin_deciban = 0.0;        ///< BF(e*) − BF(runner-up); +inf when there is no runner-up
  double shrink = 1.0;      ///< of the whole explanation
  double explained = 0.0;  ///< 1 − 1/shrink²: < 0.5 means the effects are real but most of the gap is not them
  ThirdOctaveBand band;
  bool white_after = false;  ///< is the residual after the verdict white (residual_whiteness)?
};

/// Applies the rule above.
Verdict decide(const Gap& gap, const Identification& identification, const Explanation& explanation,
               const std::vector<EffectCandidate>& candidates);

/// The rule in words, written to diagnosis.json.
std::string describe_decision_rule();

/// "main cause mic_mismatch (0.85), structure left" for a verdict with a main cause ("" without).
std::string main_cause_text(const Verdict& verdict);

}  // namespace admitgen::diagnosis

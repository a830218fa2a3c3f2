// SPDX-License-Identifier: MIT
#include "diagnosis/verdict.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace admitgen::diagnosis {

Verdict decide(const Gap& gap, const Identification& id, const Explanation& explanation,
               const std::vector<EffectCandidate>& candidates) {
  Verdict v;
  v.band = gap.bands[gap.worst].band;
  v.white_after = gap.whiteness.white;
  // No decisive effect: the gap is noise when its residual is white, real but outside the tested effects
  // when it is structured (e.g. an absorption dip no effect of the vocabulary can make).
  const auto no_explanation = [&v] {
    if (!v.white_after) v.effect = "unexplained";
    return v;
  };
  if (id.effects.empty()) return no_explanation();
  const EffectResult& best = id.effects.front();
  v.bayes_factor_deciban = best.bayes_factor_deciban;
  v.margin_deciban = id.effects.size() > 1 ? best.bayes_factor_deciban - id.effects[1].bayes_factor_deciban
                                           : std::numeric_limits<double>::infinity();
  if (best.bayes_factor_deciban < kDecisiveDeciban || explanation.steps.empty()) return no_explanation();
  for (std::size_t k = 0; k < explanation.steps.size(); ++k) {
    const ExplanationStep& step = explanation.steps[k];
    const EffectCandidate& c = candidates[step.candidate];
    VerdictMember m{c.name, {}, step.bayes_factor_deciban, step.shrink_added};
    for (const auto& p : explanation.member_parameters(k, candidates)) m.parameters.emplace_back(p.name, p.mean);
    m.parameters.insert(m.parameters.end(), c.fixed.begin(), c.fixed.end());
    v.explanation.push_back(m);
  }
  const MemberShares& shares = explanation.shares;
  for (std::size_t k = 0; k < shares.shapley.size(); ++k) v.shares.push_back({k, shares.shapley[k]});
  std::stable_sort(v.shares.begin(), v.shares.end(),
                   [](const VerdictShare& a, const VerdictShare& b) { return a.share > b.share; });
  // The largest share, when the member also explains that much alone: a share above ½ that partner members
  // cancel (their shares negative) says the members are entangled, not that this one carries the gap.
  if (!v.shares.empty() && v.shares.front().share >= kMainCauseShare &&
      shares.alone[v.shares.front().member] >= kMainCauseShare)
    v.main_cause = v.shares.front();
  for (const auto& d : explanation.dropped) {
    const EffectCandidate& c = candidates[d.candidate];
    v.dropped.push_back({c.name, c.name == "material" ? c.priors.front().name : std::string(), d.bayes_factor_deciban});
  }
  v.at_prior_bound = prior_bound_hits(explanation, candidates);
  const EffectResult& joint = explanation.joint;
  v.shrink = joint.shrink;
  v.explained = joint.explained;
  v.band = gap.bands[joint.band].band;
  v.white_after = joint.gap_after.whiteness.white;
  v.effect = v.white_after ? v.explanation.front().effect : "unexplained";
  return v;
}

std::string describe_decision_rule() {
  return fmt::format(
      "none unless the effect with the largest Bayes factor against no effect reaches {0:g} deciban (odds 100:1) "
      "(unexplained instead of none when the gap's residual is structured, lag-1 |z| >= 3); "
      "then the explanation grown from it by greedy forward selection (each added effect fitted jointly and at least "
      "{0:g} deciban better than the explanation without it; stop when none is, when the residual is white, or at "
      "{1} effects); unexplained when that explanation leaves the residual structured (lag-1 |z| >= 3), else the "
      "first effect of the explanation; with a swap step after each addition that leaves structure (an earlier member "
      "replaced by another effect when that is {0:g} deciban better; once one is, repeated over every member while "
      "structure is left), a mimic swap after each addition that leaves the residual white (each earlier member "
      "replaced by the {3} effect(s) whose single-effect correction is most like its own, kept when {0:g} deciban "
      "better) and a backward step after each addition (a "
      "member is dropped when the explanation with it is less than {0:g} deciban better than the one without it: "
      "within the decision margin the explanation with fewer parameters is kept); members listed by their share of "
      "the squared gap, the main cause named when its share is at least {2:g} and it alone explains at least {2:g} of "
      "the squared gap",
      kDecisiveDeciban, kMaxExplanationEffects, kMainCauseShare, kMimicsPerMember);
}

std::string main_cause_text(const Verdict& v) {
  if (!v.main_cause) return "";
  const VerdictMember& m = v.explanation[v.main_cause->member];
  const std::string name =
      m.effect == "material" && !m.parameters.empty() ? m.effect + " " + m.parameters.front().first : m.effect;
  return fmt::format("main cause {} ({:.2f}){}", name, v.main_cause->share, v.white_after ? "" : ", structure left");
}

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
#include "diagnosis/explanation.hpp"

#include "inference/evidence.hpp"

#include <algorithm>
#include <cstdint>

namespace admitgen::diagnosis {
namespace {


/// The index of the largest evidence (the first on ties).
std::size_t best_of(const std::vector<EffectResult>& results) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < results.size(); ++i)
    if (results[i].log_z > results[best].log_z) best = i;
  return best;
}

bool holds(const std::vector<ExplanationStep>& steps, std::size_t candidate) {
  return std::any_of(steps.begin(), steps.end(),
                     [candidate](const ExplanationStep& s) { return s.candidate == candidate; });
}

/// The candidate indices of `steps`, in step order.
std::vector<std::size_t> member_indices(const std::vector<ExplanationStep>& steps) {
  std::vector<std::size_t> out;
  for (const auto& s : steps) out.push_back(s.candidate);
  return out;
}

/// The search's state and the inputs every round shares.
struct Search {
  const Eigen::ArrayXd& f_hz;
  const Eigen::ArrayXcd& y_real;
  const Gap& gap_before;
  const std::vector<EffectCandidate>& candidates;
  const std::vector<EffectResult>& singles;
  const IdentificationSettings& settings;
  Progress& progress;
  const EffectLikelihood likelihood;
  double log_z_none = 0.0;

  /// The joint candidate of each list of candidate indices (combine_effects, members in list order),
  /// sampled from the reference densities of what `now` and the single effects know (reference()).
  std::vector<EffectCandidate> combined(const std::vector<std::vector<std::size_t>>& models,
                                        const Explanation& now) const {
    std::vector<EffectCandidate> out;
    for (const auto& m : models) {
      std::vector<const EffectCandidate*> with;
      for (const std::size_t i : m) with.push_back(&candidates[i]);
      out.push_back(combine_effects(with));
      out.back().reference = reference(m, now);
    }
    return out;
  }

  /// One reference density per parameter of the joint model `members` (docs/method.md, "Reference
  /// priors in the combined search"): a member of the explanation `now` from its joint posterior there
  /// (effect_identification.hpp kReferenceShareJoint), any other from its single-effect posterior
  /// (kReferenceShareSingle). Empty (the prior)
  /// for a model of at most one parameter, evaluated by quadrature.
  std::vector<ReferenceDensity> reference(const std::vector<std::size_t>& members, const Explanation& now) const {
    std::vector<ReferenceDensity> out;
    for (const std::size_t i : members) {
      const auto at = std::find_if(now.steps.begin(), now.steps.end(),
                                   [i](const ExplanationStep& s) { return s.candidate == i; });
      const std::vector<ReferenceDensity> q =
          at != now.steps.end()
              ? reference_densities(candidates[i].priors,
                                    now.member_parameters(static_cast<std::size_t>(at - now.steps.begin()), candidates),
                                    kReferenceShareJoint)
              : reference_densities(candidates[i].priors, singles[i].parameters, kReferenceShareSingle);
      out.insert(out.end(), q.begin(), q.end());
    }
    const bool any = std::any_of(out.begin(), out.end(), [](const ReferenceDensity& q) { return !q.uniform(); });
    if (out.size() < 2 || !any) out.clear();
    return out;
  }

  /// Jointly fitted models of candidate lists, on the seed streams from first_stream on.
  std::vector<EffectResult> evaluate(const std::vector<std::vector<std::size_t>>& models, const Explanation& now,
                                     double log_z_floor, std::uint64_t first_stream) const {
    if (models.empty()) return {};
    const std::vector<EffectCandidate> tried = combined(models, now);
    std::vector<EffectResult> out =
        evaluate_candidates(tried, likelihood, settings, log_z_floor, first_stream, progress);
    for (std::size_t k = 0; k < out.size(); ++k) fill_gap(out[k], tried[k], f_hz, y_real, gap_before);
    return out;
  }

  /// The steps of the explanation `members` (in that order) restated after a swap: member k carries the
  /// Bayes factor and the shrink of the first k + 1 members against the first k. Prefixes of one member
  /// are the single effects; longer proper prefixes are evaluated on the streams from first_stream on.
  std::vector<ExplanationStep> restate(const std::vector<std::size_t>& members, const EffectResult& joint,
                                       const Explanation& now, std::uint64_t first_stream) const {
    std::vector<std::vector<std::size_t>> longer;
    for (std::size_t k = 2; k < members.size(); ++k)
      longer.emplace_back(members.begin(), members.begin() + static_cast<std::ptrdiff_t>(k));
    const std::vector<EffectResult> evaluated = evaluate(longer, now, log_z_none, first_stream);
    std::vector<const EffectResult*> prefix{&singles[members.front()]};
    for (const auto& r : evaluated) prefix.push_back(&r);
    prefix.push_back(&joint);
    std::vector<ExplanationStep> out{{members.front(), deciban(prefix[0]->log_z, log_z_none), prefix[0]->shrink}};
    for (std::size_t k = 1; k < members.size(); ++k)
      out.push_back({members[k], deciban(prefix[k]->log_z, prefix[k - 1]->log_z),
                     prefix[k - 1]->gap_after.total / prefix[k]->gap_after.total});
    return out;
  }
};

/// The swap step after round `round` accepted a member and the residual is still structured: every
/// earlier member in turn replaced by every candidate not in the explanation (the others and their
/// order kept, all refitted jointly); the best swap is kept when it is decisive (≥ 20 dB) against the
/// explanation as it stands. Swaps sample on the streams kMax·n·round …; the restated steps on the
/// (kMax − 1)·n streams after those, so the search stays independent of the thread count.
void swap_round(const Search& search, std::uint64_t round, Explanation& out) {
  const std::size_t n = search.candidates.size();
  const std::vector<std::size_t> members = member_indices(out.steps);
  std::vector<std::vector<std::size_t>> swapped;
  for (std::size_t j = 0; j + 1 < members.size(); ++j)
    for (std::size_t i = 0; i < n; ++i) {
      if (holds(out.steps, i)) continue;
      swapped.push_back(members);
      swapped.back()[j] = i;
    }
  if (swapped.empty()) return;
  const std::uint64_t first_stream = round * kMaxExplanationEffects * n;
  std::vector<EffectResult> results = search.evaluate(swapped, out, out.joint.log_z, first_stream);
  out.rounds.push_back(results);
  const std::size_t best = best_of(results);
  if (deciban(results[best].log_z, out.joint.log_z) < kDecisiveDeciban) return;
  results[best].candidate = swapped[best].back();
  out.steps = search.restate(swapped[best], results[best], out, first_stream + (kMaxExplanationEffects - 1) * n);
  out.joint = results[best];
}

}  // namespace

std::vector<ParameterSummary> Explanation::member_parameters(std::size_t k,
                                                             const std::vector<EffectCandidate>& candidates) const {
  std::size_t offset = 0;
  for (std::size_t j = 0; j < k; ++j) offset += candidates[steps[j].candidate].priors.size();
  const std::size_t n = candidates[steps[k].candidate].priors.size();
  return {joint.parameters.begin() + static_cast<std::ptrdiff_t>(offset),
          joint.parameters.begin() + static_cast<std::ptrdiff_t>(offset + n)};
}

Explanation explain(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real, const Gap& gap_before,
                    const std::vector<EffectCandidate>& candidates, const Identification& identification,
                    const IdentificationSettings& settings, Progress& progress) {
  Explanation out;
  std::vector<EffectResult> singles(candidates.size());
  for (const auto& r : identification.effects) singles[r.candidate] = r;
  const Search search{f_hz, y_real, gap_before, candidates, singles, settings, progress,
                      EffectLikelihood(y_real), identification.log_z_none};
  const double log_z_none = search.log_z_none;
  if (singles.empty()) return out;
  const std::size_t n = candidates.size();
  const std::size_t first = best_of(singles);
  if (deciban(singles[first].log_z, log_z_none) < kDecisiveDeciban) return out;
  out.steps.push_back({first, deciban(singles[first].log_z, log_z_none), singles[first].shrink});
  out.joint = singles[first];
  for (std::uint64_t round = 1; out.steps.size() < kMaxExplanationEffects; ++round) {
    // A white residual leaves no structure in the mean; only the noise shape, which the lag-1 test
    // cannot see, may still be missing.
    const bool white = out.joint.gap_after.whiteness.white;
    std::vector<std::size_t> added;
    std::vector<std::vector<std::size_t>> models;
    for (std::size_t i = 0; i < n; ++i) {
      if (holds(out.steps, i)) continue;
      if (white && candidates[i].stage != EffectStage::noise) continue;
      models.push_back(member_indices(out.steps));
      models.back().push_back(i);
      added.push_back(i);
    }
    if (models.empty()) break;
    const std::vector<EffectCandidate> tried = search.combined(models, out);
    std::vector<EffectResult> results =
        evaluate_contenders(tried, search.likelihood, settings, out.joint.log_z, round * n, progress);
    out.rounds.push_back(results);
    const std::size_t best = best_of(results);
    const double bf = deciban(results[best].log_z, out.joint.log_z);
    if (bf < kDecisiveDeciban) break;
    results[best].candidate = added[best];
    fill_gap(results[best], tried[best], f_hz, y_real, gap_before);
    out.steps.push_back({added[best], bf, out.joint.gap_after.total / results[best].gap_after.total});
    out.joint = results[best];
    if (!out.joint.gap_after.whiteness.white) swap_round(search, round, out);
  }
  out.joint.bayes_factor_deciban = deciban(out.joint.log_z, log_z_none);
  return out;
}

}  // namespace admitgen::diagnosis

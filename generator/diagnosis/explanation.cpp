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
  const EffectLikelihood likelihood(y_real);
  const double log_z_none = identification.log_z_none;
  std::vector<EffectResult> singles(candidates.size());
  for (const auto& r : identification.effects) singles[r.candidate] = r;
  if (singles.empty()) return out;
  const std::size_t first = best_of(singles);
  if (deciban(singles[first].log_z, log_z_none) < kDecisiveDeciban) return out;
  out.steps.push_back({first, deciban(singles[first].log_z, log_z_none), singles[first].shrink});
  out.joint = singles[first];
  std::vector<const EffectCandidate*> members{&candidates[first]};
  for (std::uint64_t round = 1; out.steps.size() < kMaxExplanationEffects; ++round) {
    // A white residual leaves no structure in the mean; only the noise shape, which the lag-1 test
    // cannot see, may still be missing.
    const bool white = out.joint.gap_after.whiteness.white;
    std::vector<std::size_t> added;
    std::vector<EffectCandidate> tried;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (std::any_of(out.steps.begin(), out.steps.end(), [i](const ExplanationStep& s) { return s.candidate == i; }))
        continue;
      if (white && candidates[i].stage != EffectStage::noise) continue;
      std::vector<const EffectCandidate*> with = members;
      with.push_back(&candidates[i]);
      added.push_back(i);
      tried.push_back(combine_effects(with));
    }
    if (tried.empty()) break;
    std::vector<EffectResult> results =
        evaluate_contenders(tried, likelihood, settings, out.joint.log_z, round * candidates.size(), progress);
    out.rounds.push_back(results);
    const std::size_t best = best_of(results);
    const double bf = deciban(results[best].log_z, out.joint.log_z);
    if (bf < kDecisiveDeciban) break;
    results[best].candidate = added[best];
    fill_gap(results[best], tried[best], f_hz, y_real, gap_before);
    out.steps.push_back({added[best], bf, out.joint.gap_after.total / results[best].gap_after.total});
    out.joint = results[best];
    members.push_back(&candidates[added[best]]);
  }
  out.joint.bayes_factor_deciban = deciban(out.joint.log_z, log_z_none);
  return out;
}

}  // namespace admitgen::diagnosis

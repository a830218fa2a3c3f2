// SPDX-License-Identifier: MIT
#include "diagnosis/prior_bound.hpp"

#include "physics/material_spec.hpp"

#include <fmt/format.h>

namespace admitgen::diagnosis {
namespace {

/// Whether a bound of parameter `prior` of `effect` is a physical limit, not a range (prior_bound.hpp).
bool physical_limit(const std::string& effect, const ParameterPrior& prior, bool upper) {
  if (effect == "material") {
    const SpecParameter unnarrowed;
    return upper ? prior.hi < unnarrowed.ratio_hi : prior.lo > unnarrowed.ratio_lo;
  }
  return !upper && prior.shape == ParameterPrior::Shape::uniform && prior.lo == 0.0;
}

}  // namespace

std::vector<PriorBoundHit> prior_bound_hits(const Explanation& explanation, const std::vector<EffectCandidate>& candidates) {
  std::vector<PriorBoundHit> out;
  for (std::size_t k = 0; k < explanation.steps.size(); ++k) {
    const EffectCandidate& c = candidates[explanation.steps[k].candidate];
    const std::vector<ParameterSummary> summaries = explanation.member_parameters(k, candidates);
    for (std::size_t j = 0; j < summaries.size() && j < c.priors.size(); ++j) {
      const ParameterPrior& prior = c.priors[j];
      const ParameterSummary& s = summaries[j];
      const double u_mean = prior.cdf(s.mean);
      const bool upper = u_mean >= 1.0 - kBoundMeanShare && prior.cdf(s.ci95_hi) >= 1.0 - kBoundIntervalShare;
      const bool lower = u_mean <= kBoundMeanShare && prior.cdf(s.ci95_lo) <= kBoundIntervalShare;
      if (!(upper || lower) || physical_limit(c.name, prior, upper)) continue;
      out.push_back({c.name, prior.name, upper, upper ? prior.hi : prior.lo, s.mean,
                     fmt::format("the prior's bound, not the data, set this value: the effect may be larger than "
                                 "{} allows, or stand in for something outside the vocabulary; {}",
                                 prior.describe(), c.check)});
    }
  }
  return out;
}

std::string prior_bound_text(const PriorBoundHit& hit) {
  return fmt::format("{} {} = {:.4g} at the {} bound {:g} of its prior: {}", hit.effect, hit.parameter, hit.mean,
                     hit.upper ? "upper" : "lower", hit.bound, hit.fix);
}

}  // namespace admitgen::diagnosis

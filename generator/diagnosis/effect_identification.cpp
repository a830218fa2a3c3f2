// SPDX-License-Identifier: MIT
#include "diagnosis/effect_identification.hpp"

#include "core/rng.hpp"
#include "diagnosis/effect_likelihood.hpp"
#include "inference/evidence.hpp"
#include "inference/nested_sampler.hpp"

#include <algorithm>

namespace admitgen::diagnosis {
namespace {

/// Samples one candidate; fills evidence, posterior and the max-likelihood ϑ.
EffectResult sample_effect(const EffectCandidate& e, const EffectLikelihood& likelihood,
                           const IdentificationSettings& settings, std::uint64_t seed, std::vector<double>& best) {
  EffectResult r;
  r.name = e.name;
  r.priors = e.priors;
  r.fixed = e.fixed;
  const int dim = static_cast<int>(e.priors.size());
  if (dim == 0) {  // nothing to integrate: Z = L
    r.log_z = r.max_log_likelihood = likelihood(e.predict(nullptr));
    r.calls = 1;
    best.clear();
    return r;
  }
  const auto prior = [&e](const double* u, double* theta) {
    for (std::size_t k = 0; k < e.priors.size(); ++k) theta[k] = e.priors[k].transform(u[k]);
  };
  const auto log_l = [&](const double* theta) { return likelihood(e.predict(theta)); };
  NestedSettings ns;
  ns.live = settings.live;
  ns.dlogz = settings.dlogz;
  ns.seed = seed;
  const NestedRun run = run_nested_sampling(dim, prior, log_l, ns);
  std::vector<std::string> names;
  for (const auto& p : e.priors) names.push_back(p.name);
  r.parameters = summarize(run, names);
  r.log_z = run.log_z;
  r.log_z_error = run.log_z_error;
  r.max_log_likelihood = run.max_log_likelihood;
  r.calls = run.calls;
  const double* p = run.point(max_likelihood_index(run));
  best.assign(p, p + dim);
  return r;
}

}  // namespace

Identification identify_effects(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
                                const Eigen::ArrayXcd& y_sim, const Gap& gap_before,
                                const std::vector<EffectCandidate>& candidates, const IdentificationSettings& settings) {
  const EffectLikelihood likelihood(y_real);
  const double level = rms_level(y_real);
  Identification out;
  out.log_z_none = likelihood(EffectPrediction{y_sim, {}});
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    std::vector<double> best;
    EffectResult r = sample_effect(candidates[i], likelihood, settings, derive_seed(settings.seed, i), best);
    r.gap_after = measure_gap(f_hz, y_real, candidates[i].predict(best.empty() ? nullptr : best.data()).y, level);
    r.shrink = gap_before.total / r.gap_after.total;
    r.explained = 1.0 - 1.0 / (r.shrink * r.shrink);
    r.band = most_improved_band(gap_before.bands, r.gap_after.bands);
    out.effects.push_back(std::move(r));
  }
  std::stable_sort(out.effects.begin(), out.effects.end(),
                   [](const EffectResult& a, const EffectResult& b) { return a.log_z > b.log_z; });
  for (auto& r : out.effects) r.bayes_factor_deciban = deciban(r.log_z, out.log_z_none);
  return out;
}

}  // namespace admitgen::diagnosis

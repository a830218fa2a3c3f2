// SPDX-License-Identifier: MIT
#include "diagnosis/diagnosis_record.hpp"

#include "core/version.hpp"
#include "diagnosis/diagnosis.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen::diagnosis {
namespace {

BandEdges edges(const ThirdOctaveBand& b) { return {b.f_lo, b.f_hi, b.f_center}; }

std::vector<BandGapRecord> bands(const Gap& g) {
  std::vector<BandGapRecord> out;
  for (const auto& b : g.bands) out.push_back({edges(b.band), b.band.count, b.gap, b.gap_re, b.gap_im, b.delta_alpha_max});
  return out;
}

WhitenessRecord whiteness(const Whiteness& w) {
  return {"lag-1 autocorrelation along frequency, white when |z| < 3", w.lag1, w.z, w.white};
}

GapRecord gap_record(const Gap& g) {
  GapRecord r;
  r.metric = kGapMetric;
  r.total = g.total;
  r.total_re = g.total_re;
  r.total_im = g.total_im;
  r.delta_alpha_max = g.delta_alpha_max;
  r.whiteness = whiteness(g.whiteness);
  r.bands = bands(g);
  r.worst_band = edges(g.bands[g.worst].band);
  r.worst_band_gap = g.bands[g.worst].gap;
  return r;
}

StageRecord stage_record(const StageGap& s) {
  StageRecord r;
  r.stage = s.stage;
  r.gap = s.gap.total;
  r.bands = bands(s.gap);
  r.worst_band = edges(s.gap.bands[s.gap.worst].band);
  r.cumulative_gap = s.cumulative.total;
  r.cumulative_bands = bands(s.cumulative);
  if (!s.detail.empty()) r.detail = s.detail;
  return r;
}

EffectRecord effect_record(const EffectResult& e, const Gap& before) {
  EffectRecord r;
  r.effect = e.name;
  for (std::size_t k = 0; k < e.parameters.size(); ++k) {
    const auto& p = e.parameters[k];
    r.parameters.emplace_back(p.name, p.mean);
    r.parameter_summary.push_back({p.name, p.mean, p.std, p.ci95_lo, p.ci95_hi, p.max_likelihood, e.priors[k].describe()});
  }
  for (const auto& [name, value] : e.fixed) {
    r.parameters.emplace_back(name, value);
    r.fixed_parameters.emplace_back(name, value);
  }
  r.log_bayes_factor_deciban = e.bayes_factor_deciban;
  r.log_evidence = e.log_z;
  r.log_evidence_error = e.log_z_error;
  r.max_log_likelihood = e.max_log_likelihood;
  r.likelihood_calls = e.calls;
  r.gap_after = e.gap_after.total;
  r.shrink = e.shrink;
  r.explained_fraction = e.explained;
  r.band = edges(before.bands[e.band].band);
  r.bands_after = bands(e.gap_after);
  r.whiteness_after = whiteness(e.gap_after.whiteness);
  r.evidence_method = e.method;
  r.stopped_early = e.stopped_early;
  return r;
}

VerdictRecord verdict_record(const Verdict& v) {
  VerdictRecord r;
  r.effect = v.effect;
  for (const auto& m : v.explanation) r.explanation.push_back({m.effect, m.parameters, m.bayes_factor_deciban, m.shrink_added});
  const auto share = [&v](const VerdictShare& s) {
    return ShareRecord{v.explanation[s.member].effect, static_cast<std::int64_t>(s.member), s.share};
  };
  for (const auto& s : v.shares) r.shares.push_back(share(s));
  if (v.main_cause) r.main_cause = share(*v.main_cause);
  for (const auto& d : v.dropped)
    r.dropped.push_back({d.effect, d.parameter.empty() ? std::nullopt : std::optional<std::string>(d.parameter),
                         d.bayes_factor_deciban,
                         fmt::format("the explanation with it is less than {:g} deciban better than the one without it: "
                                     "within the decision margin, the one with fewer parameters is kept",
                                     kDecisiveDeciban)});
  if (!v.at_prior_bound.empty()) {
    r.at_prior_bound.emplace();
    for (const auto& h : v.at_prior_bound)
      r.at_prior_bound->push_back({h.effect, h.parameter, h.upper ? "upper" : "lower", h.bound, h.mean, h.fix});
  }
  r.shrink = v.shrink;
  r.explained_fraction = v.explained;
  r.band = edges(v.band);
  r.log_bayes_factor_deciban = v.bayes_factor_deciban;
  if (std::isfinite(v.margin_deciban)) r.margin_deciban = v.margin_deciban;
  r.residual_white_after = v.white_after;
  r.rule = describe_decision_rule();
  return r;
}

DiagnosisSettingsRecord settings_record(const Diagnosis& d) {
  DiagnosisSettingsRecord r;
  r.live = d.settings.sampler.live;
  r.dlogz = d.settings.sampler.stop_dlogz();
  r.seed = d.settings.sampler.seed;
  r.evidence = describe_evidence_methods(d.settings);
  r.likelihood = "marginal-gaussian (noise std marginalised, Jeffreys prior), K = 2N, "
                 "per-point noise shape for heteroscedastic_noise";
  r.decision_rule = describe_decision_rule();
  for (const auto& c : d.candidates) {  // the material candidates share one entry, a prior per parameter
    if (r.priors.empty() || r.priors.back().first != c.name) r.priors.emplace_back(c.name, std::vector<EffectPriorRecord>{});
    auto& priors = r.priors.back().second;
    for (const auto& prior : c.priors) priors.push_back({prior.name, prior.describe(), std::nullopt});
    for (const auto& [name, value] : c.fixed) priors.push_back({name, std::nullopt, value});
  }
  return r;
}

}  // namespace

DiagnosisRecord diagnosis_record(const Diagnosis& d) {
  DiagnosisRecord r;
  r.version = kVersion;
  r.input.real_path = d.real_path;
  r.input.real_sha256 = d.real_sha256;
  r.input.sim = d.sim_description;
  r.input.points = d.f_hz.size();
  r.input.f_min_hz = d.f_hz[0];
  r.input.f_max_hz = d.f_hz[d.f_hz.size() - 1];
  r.input.level_rms_y = d.level;
  r.input.warnings = d.warnings;
  r.settings = settings_record(d);
  r.gap = gap_record(d.gap);
  for (const auto& s : d.stages) r.stages.push_back(stage_record(s));
  r.log_evidence_none = d.identification.log_z_none;
  for (const auto& e : d.identification.effects) r.effects.push_back(effect_record(e, d.gap));
  r.verdict = verdict_record(d.verdict);
  return r;
}

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
#include "diagnosis/diagnosis_json.hpp"

#include "core/version.hpp"

#include <cmath>

namespace admitgen::diagnosis {
namespace {

using Json = nlohmann::ordered_json;

Json band_edges(const ThirdOctaveBand& b) { return Json{{"f_lo", b.f_lo}, {"f_hi", b.f_hi}, {"f_center", b.f_center}}; }

Json bands_json(const Gap& g) {
  Json out = Json::array();
  for (const auto& b : g.bands) {
    Json j = band_edges(b.band);
    j["points"] = b.band.count;
    j["gap"] = b.gap;
    j["gap_re"] = b.gap_re;
    j["gap_im"] = b.gap_im;
    j["delta_alpha_max"] = b.delta_alpha_max;
    out.push_back(j);
  }
  return out;
}

Json whiteness_json(const Whiteness& w) {
  return Json{{"test", "lag-1 autocorrelation along frequency, white when |z| < 3"},
              {"lag1", w.lag1},
              {"z", w.z},
              {"white", w.white}};
}

Json gap_json(const Gap& g, bool with_metric) {
  Json j;
  if (with_metric) j["metric"] = kGapMetric;
  j["total"] = g.total;
  j["total_re"] = g.total_re;
  j["total_im"] = g.total_im;
  j["delta_alpha_max"] = g.delta_alpha_max;
  j["whiteness"] = whiteness_json(g.whiteness);
  j["bands"] = bands_json(g);
  Json worst = band_edges(g.bands[g.worst].band);
  worst["gap"] = g.bands[g.worst].gap;
  j["worst_band"] = worst;
  return j;
}

Json stage_json(const StageGap& s) {
  Json j{{"stage", s.stage},
         {"gap", s.gap.total},
         {"bands", bands_json(s.gap)},
         {"worst_band", band_edges(s.gap.bands[s.gap.worst].band)},
         {"cumulative", {{"gap", s.cumulative.total}, {"bands", bands_json(s.cumulative)}}}};
  if (!s.detail.empty()) j["detail"] = s.detail;
  return j;
}

Json effect_json(const EffectResult& r, const Gap& before) {
  Json params = Json::object(), summary = Json::object(), fixed = Json::object();
  for (std::size_t k = 0; k < r.parameters.size(); ++k) {
    const auto& p = r.parameters[k];
    params[p.name] = p.mean;
    summary[p.name] = Json{{"mean", p.mean},
                           {"std", p.std},
                           {"ci95", {p.ci95_lo, p.ci95_hi}},
                           {"max_likelihood", p.max_likelihood},
                           {"prior", r.priors[k].describe()}};
  }
  for (const auto& [name, value] : r.fixed) {
    params[name] = value;
    fixed[name] = value;
  }
  return Json{{"effect", r.name},
              {"parameters", params},
              {"parameter_summary", summary},
              {"fixed_parameters", fixed},
              {"log_bayes_factor_deciban", r.bayes_factor_deciban},
              {"log_evidence", r.log_z},
              {"log_evidence_error", r.log_z_error},
              {"max_log_likelihood", r.max_log_likelihood},
              {"likelihood_calls", r.calls},
              {"gap_after", r.gap_after.total},
              {"shrink", r.shrink},
              {"explained_fraction", r.explained},
              {"band", band_edges(before.bands[r.band].band)},
              {"bands_after", bands_json(r.gap_after)},
              {"whiteness_after", whiteness_json(r.gap_after.whiteness)},
              {"evidence_method", r.method},
              {"stopped_early", r.stopped_early}};
}

Json verdict_json(const Verdict& v) {
  Json j{{"effect", v.effect},
         {"shrink", v.shrink},
         {"explained_fraction", v.explained},
         {"band", {{"f_lo", v.band.f_lo}, {"f_hi", v.band.f_hi}, {"f_center", v.band.f_center}}},
         {"log_bayes_factor_deciban", v.bayes_factor_deciban}};
  j["margin_deciban"] = std::isfinite(v.margin_deciban) ? Json(v.margin_deciban) : Json(nullptr);
  j["residual_white_after"] = v.white_after;
  j["rule"] = describe_decision_rule();
  return j;
}

Json settings_json(const Diagnosis& d) {
  Json priors = Json::object();
  for (const auto& c : d.candidates) {
    Json p = Json::object();
    for (const auto& prior : c.priors) p[prior.name] = prior.describe();
    for (const auto& [name, value] : c.fixed) p[name] = Json{{"fixed", value}};
    priors[c.name] = p;
  }
  return Json{{"live", d.settings.sampler.live},
              {"dlogz", d.settings.sampler.dlogz},
              {"seed", d.settings.sampler.seed},
              {"evidence", describe_evidence_methods(d.settings)},
              {"likelihood", "marginal-gaussian (noise std marginalised, Jeffreys prior), K = 2N, "
                             "per-point noise shape for heteroscedastic_noise"},
              {"decision_rule", describe_decision_rule()},
              {"priors", priors}};
}

}  // namespace

Json diagnosis_json(const Diagnosis& d) {
  Json j;
  j["schema"] = "admitgen.diagnosis/1";
  j["version"] = kVersion;
  j["input"] = Json{{"real", {{"path", d.real_path}, {"sha256", d.real_sha256}}},
                    {"sim", d.sim_description},
                    {"points", d.f_hz.size()},
                    {"f_min_hz", d.f_hz[0]},
                    {"f_max_hz", d.f_hz[d.f_hz.size() - 1]},
                    {"level_rms_y", d.level},
                    {"warnings", d.warnings}};
  j["settings"] = settings_json(d);
  j["gap"] = gap_json(d.gap, true);
  j["stages"] = Json::array();
  for (const auto& s : d.stages) j["stages"].push_back(stage_json(s));
  j["log_evidence_none"] = d.identification.log_z_none;
  j["effects"] = Json::array();
  for (const auto& r : d.identification.effects) j["effects"].push_back(effect_json(r, d.gap));
  j["verdict"] = verdict_json(d.verdict);
  return j;
}

std::string diagnosis_text(const Diagnosis& d) { return diagnosis_json(d).dump(2) + "\n"; }

}  // namespace admitgen::diagnosis

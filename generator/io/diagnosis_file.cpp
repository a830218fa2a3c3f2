// SPDX-License-Identifier: MIT
#include "io/diagnosis_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "io/record_fields.hpp"

#include <fmt/format.h>

namespace admitgen::io {

// ---- the field lists of diagnosis.json (docs/formats.md, "diagnosis.json") ------------------------

namespace {

/// The priors by effect: {effect: {parameter: "prior" | {"fixed": value}}}.
struct EffectPriors {
  using Priors = std::vector<std::pair<std::string, std::vector<diagnosis::EffectPriorRecord>>>;
  Json write(const Priors& priors) const {
    Json out = Json::object();
    for (const auto& [effect, list] : priors) {
      Json p = Json::object();
      for (const auto& prior : list) p[prior.name] = prior.fixed ? Json{{"fixed", *prior.fixed}} : Json(*prior.description);
      out[effect] = p;
    }
    return out;
  }
  void read(const Field& f, Priors& priors) const {
    priors.clear();
    for (const auto& [effect, list] : ObjectReader(f).members()) {
      std::vector<diagnosis::EffectPriorRecord> effect_priors;
      for (const auto& [name, v] : ObjectReader(list).members()) {
        if (v.json().is_string()) {
          effect_priors.push_back({name, v.text(), std::nullopt});
        } else {
          ObjectReader fixed(v);
          effect_priors.push_back({name, std::nullopt, fixed.required("fixed").number()});
          fixed.finish();
        }
      }
      priors.emplace_back(effect, effect_priors);
    }
  }
};

}  // namespace

template <class V>
void fields(V& v, diagnosis::BandEdges& b) {
  v("f_lo", b.f_lo);
  v("f_hi", b.f_hi);
  v("f_center", b.f_center);
}

template <class V>
void fields(V& v, diagnosis::BandGapRecord& b) {
  fields(v, b.band);
  v("points", b.points);
  v("gap", b.gap);
  v("gap_re", b.gap_re);
  v("gap_im", b.gap_im);
  v("delta_alpha_max", b.delta_alpha_max);
}

template <class V>
void fields(V& v, diagnosis::WhitenessRecord& w) {
  v("test", w.test);
  v("lag1", w.lag1);
  v("z", w.z);
  v("white", w.white);
}

template <class V>
void fields(V& v, diagnosis::GapRecord& g) {
  v("metric", g.metric);
  v("total", g.total);
  v("total_re", g.total_re);
  v("total_im", g.total_im);
  v("delta_alpha_max", g.delta_alpha_max);
  v("whiteness", g.whiteness);
  v("bands", g.bands);
  v.object("worst_band", [&g](auto& w) {
    w.expect(!g.bands.empty(), "a gap needs at least one band");
    fields(w, g.worst_band);
    w("gap", g.worst_band_gap);
  });
}

template <class V>
void fields(V& v, diagnosis::StageRecord& s) {
  v("stage", s.stage);
  v("gap", s.gap);
  v("bands", s.bands);
  v("worst_band", s.worst_band);
  v.object("cumulative", [&s](auto& w) {
    w("gap", s.cumulative_gap);
    w("bands", s.cumulative_bands);
  });
  v("detail", s.detail);
}

/// Keyed by its name (EffectRecord::parameter_summary).
template <class V>
void fields(V& v, diagnosis::EffectParameterRecord& p) {
  v("mean", p.mean);
  v("std", p.std);
  v.pair("ci95", p.ci95_lo, p.ci95_hi);
  v("max_likelihood", p.max_likelihood);
  v("prior", p.prior);
}

template <class V>
void fields(V& v, diagnosis::EffectRecord& e) {
  v("effect", e.effect);
  v("parameters", e.parameters);
  v.by_name("parameter_summary", e.parameter_summary);
  v("fixed_parameters", e.fixed_parameters);
  v("log_bayes_factor_deciban", e.log_bayes_factor_deciban);
  v("log_evidence", e.log_evidence);
  v("log_evidence_error", e.log_evidence_error);
  v("max_log_likelihood", e.max_log_likelihood);
  v("likelihood_calls", e.likelihood_calls);
  v("gap_after", e.gap_after);
  v("shrink", e.shrink);
  v("explained_fraction", e.explained_fraction);
  v("band", e.band);
  v("bands_after", e.bands_after);
  v("whiteness_after", e.whiteness_after);
  v("evidence_method", e.evidence_method);
  v("stopped_early", e.stopped_early);
}

template <class V>
void fields(V& v, diagnosis::ExplanationMemberRecord& m) {
  v("effect", m.effect);
  v("parameters", m.parameters);
  v("log_bayes_factor_deciban", m.log_bayes_factor_deciban);
  v("shrink_added", m.shrink_added);
}

template <class V>
void fields(V& v, diagnosis::ShareRecord& r) {
  v("effect", r.effect);
  v("member", r.member);
  v("share", r.share);
}

template <class V>
void fields(V& v, diagnosis::DroppedMemberRecord& r) {
  v("effect", r.effect);
  v("parameter", r.parameter);
  v("log_bayes_factor_deciban", r.log_bayes_factor_deciban);
  v("reason", r.reason);
}

template <class V>
void fields(V& v, diagnosis::PriorBoundRecord& r) {
  v("effect", r.effect);
  v("parameter", r.parameter);
  v("bound", r.bound);
  v("bound_value", r.bound_value);
  v("mean", r.mean);
  v("fix", r.fix);
}

template <class V>
void fields(V& v, diagnosis::VerdictRecord& r) {
  v("effect", r.effect);
  v.since(2, [&r](auto& w) { w("explanation", r.explanation); });
  v.since(3, [&r](auto& w) {
    w("shares", r.shares);
    w("main_cause", r.main_cause, kNullable);
    w("dropped", r.dropped);
    w("at_prior_bound", r.at_prior_bound);
  });
  v("shrink", r.shrink);
  v("explained_fraction", r.explained_fraction);
  v("band", r.band);
  v("log_bayes_factor_deciban", r.log_bayes_factor_deciban);
  v("margin_deciban", r.margin_deciban, kNullable);
  v("residual_white_after", r.residual_white_after);
  v("rule", r.rule);
}

template <class V>
void fields(V& v, diagnosis::DiagnosisSettingsRecord& s) {
  v("live", s.live);
  v("dlogz", s.dlogz);
  v("seed", s.seed);
  v("evidence", s.evidence);
  v("likelihood", s.likelihood);
  v("decision_rule", s.decision_rule);
  v.custom("priors", s.priors, EffectPriors{});
}

template <class V>
void fields(V& v, diagnosis::DiagnosisInputRecord& in) {
  v.object("real", [&in](auto& w) {
    w("path", in.real_path);
    w("sha256", in.real_sha256);
  });
  v("sim", in.sim);
  v("points", in.points);
  v("f_min_hz", in.f_min_hz);
  v("f_max_hz", in.f_max_hz);
  v("level_rms_y", in.level_rms_y);
  v("warnings", in.warnings, kPlain);
}

template <class V>
void fields(V& v, diagnosis::DiagnosisRecord& d) {
  v("schema", d.schema);
  v("version", d.version);
  v("input", d.input);
  v("settings", d.settings);
  v("gap", d.gap);
  v("stages", d.stages);
  v("log_evidence_none", d.log_evidence_none);
  v("effects", d.effects);
  v("verdict", d.verdict);
}

// ---- writer and reader ----------------------------------------------------------------------------

namespace {

/// A /1 verdict has no explanation: its one effect (with the parameters of its entry in "effects") is it.
std::vector<diagnosis::ExplanationMemberRecord> explanation_of_v1(const diagnosis::VerdictRecord& v,
                                                                  const std::vector<diagnosis::EffectRecord>& effects) {
  if (v.effect == "none") return {};
  diagnosis::ExplanationMemberRecord m{v.effect, {}, v.log_bayes_factor_deciban, v.shrink};
  for (const auto& e : effects)
    if (e.effect == v.effect) {
      m.parameters = e.parameters;
      break;
    }
  return {m};
}

}  // namespace

std::string diagnosis_text(const diagnosis::DiagnosisRecord& d) { return write_record(d).dump(2) + "\n"; }

diagnosis::DiagnosisRecord parse_diagnosis(const std::string& text, const std::string& file) {
  const Json doc = parse_json(text, file);
  // Older schemas are read as the current one: what they lack stays empty.
  const char* schema = diagnosis::kDiagnosisSchema;
  int version = kLatestVersion;
  if (doc.is_object() && doc.contains("schema")) {
    if (doc["schema"] == diagnosis::kDiagnosisSchemaV1) schema = diagnosis::kDiagnosisSchemaV1, version = 1;
    if (doc["schema"] == diagnosis::kDiagnosisSchemaV2) schema = diagnosis::kDiagnosisSchemaV2, version = 2;
  }
  diagnosis::DiagnosisRecord d;
  read_record(document_root(doc, file, schema, "diagnosis"), d, version);
  if (version == 1) d.verdict.explanation = explanation_of_v1(d.verdict, d.effects);  // its one effect is its explanation
  d.schema = diagnosis::kDiagnosisSchema;
  return d;
}

diagnosis::DiagnosisRecord read_diagnosis_file(const std::string& path) {
  return parse_diagnosis(read_bounded(path, kMaxDocumentBytes, "diagnosis"), path);
}

std::string passive_diagnosis_text(const diagnosis::PassiveDiagnosis& d) {
  Json doc = Json::object();
  doc["schema"] = "admitgen.passive_diagnosis/1";
  doc["real"] = {{"path", d.real_path}, {"sha256", d.real_sha256}, {"points", d.points}, {"scan_points", d.scan_points}};
  doc["reference"] = "passive";
  doc["noise_std"] = d.noise_std;
  doc["passive_bound_before"] = d.bound_before;
  doc["noise_ratio_before"] = d.noise_ratio_before;
  doc["band"] = {{"f_lo", d.band_lo_hz}, {"f_hi", d.band_hi_hz}, {"f_center", d.band_center_hz},
                 {"noise_ratio", d.band_noise_ratio}};
  Json effects = Json::array();
  for (const auto& e : d.effects) {
    Json parameters = Json::array();
    for (std::size_t k = 0; k < e.priors.size(); ++k)
      parameters.push_back({{"name", e.priors[k].name},
                            {"prior", e.priors[k].describe()},
                            {"best", e.best[k]},
                            {"mean", e.mean[k]},
                            {"interval95", {e.lo95[k], e.hi95[k]}}});
    Json at_bound = Json::array();
    for (const auto& p : e.at_bound) at_bound.push_back(p);
    effects.push_back({{"effect", e.name},
                       {"parameters", parameters},
                       {"bayes_factor_deciban", e.bayes_factor_deciban},
                       {"passive_bound_after", e.bound_after},
                       {"noise_ratio_after", e.noise_ratio_after},
                       {"at_prior_bound", at_bound},
                       {"evaluations", e.evaluations}});
  }
  doc["effects"] = effects;
  doc["verdict"] = d.verdict;
  Json warnings = Json::array();
  for (const auto& w : d.warnings) warnings.push_back(w);
  doc["warnings"] = warnings;
  return doc.dump(2) + "\n";
}

std::vector<KeyNode> diagnosis_keys() { return record_keys<diagnosis::DiagnosisRecord>(); }

}  // namespace admitgen::io

// SPDX-License-Identifier: MIT
#include "io/diagnosis_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "io/json_fields.hpp"

#include <fmt/format.h>

namespace admitgen::io {
namespace {

using namespace admitgen::diagnosis;

// ---- writer ---------------------------------------------------------------------------------------

Json edges_json(const BandEdges& b) { return Json{{"f_lo", b.f_lo}, {"f_hi", b.f_hi}, {"f_center", b.f_center}}; }

Json bands_json(const std::vector<BandGapRecord>& bands) {
  Json out = Json::array();
  for (const auto& b : bands) {
    Json j = edges_json(b.band);
    j["points"] = b.points;
    j["gap"] = b.gap;
    j["gap_re"] = b.gap_re;
    j["gap_im"] = b.gap_im;
    j["delta_alpha_max"] = b.delta_alpha_max;
    out.push_back(j);
  }
  return out;
}

Json whiteness_json(const WhitenessRecord& w) {
  return Json{{"test", w.test}, {"lag1", w.lag1}, {"z", w.z}, {"white", w.white}};
}

Json gap_json(const GapRecord& g) {
  Json j;
  j["metric"] = g.metric;
  j["total"] = g.total;
  j["total_re"] = g.total_re;
  j["total_im"] = g.total_im;
  j["delta_alpha_max"] = g.delta_alpha_max;
  j["whiteness"] = whiteness_json(g.whiteness);
  j["bands"] = bands_json(g.bands);
  Json worst = edges_json(g.worst_band);
  worst["gap"] = g.worst_band_gap;
  j["worst_band"] = worst;
  return j;
}

Json stage_json(const StageRecord& s) {
  Json j{{"stage", s.stage},
         {"gap", s.gap},
         {"bands", bands_json(s.bands)},
         {"worst_band", edges_json(s.worst_band)},
         {"cumulative", {{"gap", s.cumulative_gap}, {"bands", bands_json(s.cumulative_bands)}}}};
  if (s.detail) j["detail"] = *s.detail;
  return j;
}

Json effect_json(const EffectRecord& e) {
  Json summary = Json::object();
  for (const auto& p : e.parameter_summary)
    summary[p.name] = Json{{"mean", p.mean},
                           {"std", p.std},
                           {"ci95", {p.ci95_lo, p.ci95_hi}},
                           {"max_likelihood", p.max_likelihood},
                           {"prior", p.prior}};
  Json j{{"effect", e.effect},
              {"parameters", numbers_by_name_json(e.parameters)},
              {"parameter_summary", summary},
              {"fixed_parameters", numbers_by_name_json(e.fixed_parameters)},
              {"log_bayes_factor_deciban", e.log_bayes_factor_deciban},
              {"log_evidence", e.log_evidence},
              {"log_evidence_error", e.log_evidence_error},
              {"max_log_likelihood", e.max_log_likelihood},
              {"likelihood_calls", e.likelihood_calls},
              {"gap_after", e.gap_after},
              {"shrink", e.shrink},
              {"explained_fraction", e.explained_fraction},
              {"band", edges_json(e.band)},
              {"bands_after", bands_json(e.bands_after)},
              {"whiteness_after", whiteness_json(e.whiteness_after)}};
  if (e.evidence_method) j["evidence_method"] = *e.evidence_method;
  if (e.stopped_early) j["stopped_early"] = *e.stopped_early;
  return j;
}

Json verdict_json(const VerdictRecord& v) {
  Json explanation = Json::array();
  for (const auto& m : v.explanation)
    explanation.push_back(Json{{"effect", m.effect},
                               {"parameters", numbers_by_name_json(m.parameters)},
                               {"log_bayes_factor_deciban", m.log_bayes_factor_deciban},
                               {"shrink_added", m.shrink_added}});
  const auto share_json = [](const ShareRecord& r) {
    return Json{{"effect", r.effect}, {"member", r.member}, {"share", r.share}};
  };
  Json shares = Json::array();
  for (const auto& r : v.shares) shares.push_back(share_json(r));
  Json dropped = Json::array();
  for (const auto& d : v.dropped) {
    Json j{{"effect", d.effect}};
    if (d.parameter) j["parameter"] = *d.parameter;
    j["log_bayes_factor_deciban"] = d.log_bayes_factor_deciban;
    j["reason"] = d.reason;
    dropped.push_back(j);
  }
  Json j{{"effect", v.effect},
         {"explanation", explanation},
         {"shares", shares},
         {"main_cause", v.main_cause ? share_json(*v.main_cause) : Json(nullptr)},
         {"dropped", dropped},
         {"shrink", v.shrink},
         {"explained_fraction", v.explained_fraction},
         {"band", edges_json(v.band)},
         {"log_bayes_factor_deciban", v.log_bayes_factor_deciban}};
  j["margin_deciban"] = v.margin_deciban ? Json(*v.margin_deciban) : Json(nullptr);
  j["residual_white_after"] = v.residual_white_after;
  j["rule"] = v.rule;
  return j;
}

Json settings_json(const DiagnosisSettingsRecord& s) {
  Json priors = Json::object();
  for (const auto& [effect, list] : s.priors) {
    Json p = Json::object();
    for (const auto& prior : list) p[prior.name] = prior.fixed ? Json{{"fixed", *prior.fixed}} : Json(*prior.description);
    priors[effect] = p;
  }
  Json j{{"live", s.live}, {"dlogz", s.dlogz}, {"seed", s.seed}};
  if (s.evidence) j["evidence"] = *s.evidence;
  j["likelihood"] = s.likelihood;
  j["decision_rule"] = s.decision_rule;
  j["priors"] = priors;
  return j;
}

// ---- reader ---------------------------------------------------------------------------------------

BandEdges read_edges(ObjectReader& o) {
  return {o.required("f_lo").number(), o.required("f_hi").number(), o.required("f_center").number()};
}

BandEdges read_edges(const Field& f) {
  ObjectReader o(f);
  const BandEdges b = read_edges(o);
  o.finish();
  return b;
}

std::vector<BandGapRecord> read_bands(const Field& f) {
  std::vector<BandGapRecord> out;
  for (const auto& e : f.elements()) {
    ObjectReader o(e);
    BandGapRecord b;
    b.band = read_edges(o);
    b.points = o.required("points").integer();
    b.gap = o.required("gap").number();
    b.gap_re = o.required("gap_re").number();
    b.gap_im = o.required("gap_im").number();
    b.delta_alpha_max = o.required("delta_alpha_max").number();
    o.finish();
    out.push_back(b);
  }
  return out;
}

WhitenessRecord read_whiteness(const Field& f) {
  ObjectReader o(f);
  WhitenessRecord w{o.required("test").text(), o.required("lag1").number(), o.required("z").number(),
                    o.required("white").boolean()};
  o.finish();
  return w;
}

GapRecord read_gap(const Field& f) {
  ObjectReader o(f);
  GapRecord g;
  g.metric = o.required("metric").text();
  g.total = o.required("total").number();
  g.total_re = o.required("total_re").number();
  g.total_im = o.required("total_im").number();
  g.delta_alpha_max = o.required("delta_alpha_max").number();
  g.whiteness = read_whiteness(o.required("whiteness"));
  g.bands = read_bands(o.required("bands"));
  const Field worst = o.required("worst_band");
  if (g.bands.empty()) worst.fail("a gap needs at least one band");
  ObjectReader w(worst);
  g.worst_band = read_edges(w);
  g.worst_band_gap = w.required("gap").number();
  w.finish();
  o.finish();
  return g;
}

StageRecord read_stage(const Field& f) {
  ObjectReader o(f);
  StageRecord s;
  s.stage = o.required("stage").text();
  s.gap = o.required("gap").number();
  s.bands = read_bands(o.required("bands"));
  s.worst_band = read_edges(o.required("worst_band"));
  ObjectReader c(o.required("cumulative"));
  s.cumulative_gap = c.required("gap").number();
  s.cumulative_bands = read_bands(c.required("bands"));
  c.finish();
  if (auto v = o.optional("detail")) s.detail = v->text();
  o.finish();
  return s;
}

EffectRecord read_effect(const Field& f) {
  ObjectReader o(f);
  EffectRecord e;
  e.effect = o.required("effect").text();
  e.parameters = o.required("parameters").numbers_by_name();
  for (const auto& [name, v] : ObjectReader(o.required("parameter_summary")).members()) {
    ObjectReader p(v);
    EffectParameterRecord r;
    r.name = name;
    r.mean = p.required("mean").number();
    r.std = p.required("std").number();
    const auto ci = p.required("ci95").number_pair();
    r.ci95_lo = ci[0];
    r.ci95_hi = ci[1];
    r.max_likelihood = p.required("max_likelihood").number();
    r.prior = p.required("prior").text();
    p.finish();
    e.parameter_summary.push_back(r);
  }
  e.fixed_parameters = o.required("fixed_parameters").numbers_by_name();
  e.log_bayes_factor_deciban = o.required("log_bayes_factor_deciban").number();
  e.log_evidence = o.required("log_evidence").number();
  e.log_evidence_error = o.required("log_evidence_error").number();
  e.max_log_likelihood = o.required("max_log_likelihood").number();
  e.likelihood_calls = o.required("likelihood_calls").integer();
  e.gap_after = o.required("gap_after").number();
  e.shrink = o.required("shrink").number();
  e.explained_fraction = o.required("explained_fraction").number();
  e.band = read_edges(o.required("band"));
  e.bands_after = read_bands(o.required("bands_after"));
  e.whiteness_after = read_whiteness(o.required("whiteness_after"));
  if (const auto m = o.optional("evidence_method")) e.evidence_method = m->text();
  if (const auto s = o.optional("stopped_early")) e.stopped_early = s->boolean();
  o.finish();
  return e;
}

/// A /1 verdict has no explanation: its one effect (with the parameters of its entry in "effects") is it.
std::vector<ExplanationMemberRecord> explanation_of_v1(const VerdictRecord& v, const std::vector<EffectRecord>& effects) {
  if (v.effect == "none") return {};
  ExplanationMemberRecord m{v.effect, {}, v.log_bayes_factor_deciban, v.shrink};
  for (const auto& e : effects)
    if (e.effect == v.effect) {
      m.parameters = e.parameters;
      break;
    }
  return {m};
}

ShareRecord read_share(const Field& f) {
  ObjectReader o(f);
  ShareRecord r;
  r.effect = o.required("effect").text();
  r.member = o.required("member").integer();
  r.share = o.required("share").number();
  o.finish();
  return r;
}

DroppedMemberRecord read_dropped(const Field& f) {
  ObjectReader o(f);
  DroppedMemberRecord r;
  r.effect = o.required("effect").text();
  if (const auto p = o.optional("parameter")) r.parameter = p->text();
  r.log_bayes_factor_deciban = o.required("log_bayes_factor_deciban").number();
  r.reason = o.required("reason").text();
  o.finish();
  return r;
}

/// The verdict of a file of the current schema; of /2 (no shares, main cause or dropped members) and /1
/// (no explanation either) when `schema` says so.
VerdictRecord read_verdict(const Field& f, const std::string& schema) {
  const bool v1 = schema == kDiagnosisSchemaV1;
  ObjectReader o(f);
  VerdictRecord v;
  v.effect = o.required("effect").text();
  if (!v1)
    for (const auto& m : o.required("explanation").elements()) {
      ObjectReader r(m);
      ExplanationMemberRecord member;
      member.effect = r.required("effect").text();
      member.parameters = r.required("parameters").numbers_by_name();
      member.log_bayes_factor_deciban = r.required("log_bayes_factor_deciban").number();
      member.shrink_added = r.required("shrink_added").number();
      r.finish();
      v.explanation.push_back(member);
    }
  if (schema == kDiagnosisSchema) {
    for (const auto& s : o.required("shares").elements()) v.shares.push_back(read_share(s));
    if (const Field m = o.required("main_cause"); !m.json().is_null()) v.main_cause = read_share(m);
    for (const auto& d : o.required("dropped").elements()) v.dropped.push_back(read_dropped(d));
  }
  v.shrink = o.required("shrink").number();
  v.explained_fraction = o.required("explained_fraction").number();
  v.band = read_edges(o.required("band"));
  v.log_bayes_factor_deciban = o.required("log_bayes_factor_deciban").number();
  if (const Field m = o.required("margin_deciban"); !m.json().is_null()) v.margin_deciban = m.number();
  v.residual_white_after = o.required("residual_white_after").boolean();
  v.rule = o.required("rule").text();
  o.finish();
  return v;
}

DiagnosisSettingsRecord read_settings(const Field& f) {
  ObjectReader o(f);
  DiagnosisSettingsRecord s;
  s.live = o.required("live").integer();
  s.dlogz = o.required("dlogz").number();
  s.seed = o.required("seed").unsigned_integer();
  if (const auto e = o.optional("evidence")) s.evidence = e->text();
  s.likelihood = o.required("likelihood").text();
  s.decision_rule = o.required("decision_rule").text();
  for (const auto& [effect, list] : ObjectReader(o.required("priors")).members()) {
    std::vector<EffectPriorRecord> priors;
    for (const auto& [name, v] : ObjectReader(list).members()) {
      if (v.json().is_string()) {
        priors.push_back({name, v.text(), std::nullopt});
      } else {
        ObjectReader fixed(v);
        priors.push_back({name, std::nullopt, fixed.required("fixed").number()});
        fixed.finish();
      }
    }
    s.priors.emplace_back(effect, priors);
  }
  o.finish();
  return s;
}

DiagnosisInputRecord read_input(const Field& f) {
  ObjectReader o(f);
  DiagnosisInputRecord in;
  ObjectReader real(o.required("real"));
  in.real_path = real.required("path").text();
  in.real_sha256 = real.required("sha256").text();
  real.finish();
  in.sim = o.required("sim").text();
  in.points = o.required("points").integer();
  in.f_min_hz = o.required("f_min_hz").number();
  in.f_max_hz = o.required("f_max_hz").number();
  in.level_rms_y = o.required("level_rms_y").number();
  in.warnings = o.required("warnings").texts();
  o.finish();
  return in;
}

}  // namespace

std::string diagnosis_text(const DiagnosisRecord& d) {
  Json j;
  j["schema"] = d.schema;
  j["version"] = d.version;
  j["input"] = Json{{"real", {{"path", d.input.real_path}, {"sha256", d.input.real_sha256}}},
                    {"sim", d.input.sim},
                    {"points", d.input.points},
                    {"f_min_hz", d.input.f_min_hz},
                    {"f_max_hz", d.input.f_max_hz},
                    {"level_rms_y", d.input.level_rms_y},
                    {"warnings", plain_texts(d.input.warnings)}};
  j["settings"] = settings_json(d.settings);
  j["gap"] = gap_json(d.gap);
  j["stages"] = Json::array();
  for (const auto& s : d.stages) j["stages"].push_back(stage_json(s));
  j["log_evidence_none"] = d.log_evidence_none;
  j["effects"] = Json::array();
  for (const auto& e : d.effects) j["effects"].push_back(effect_json(e));
  j["verdict"] = verdict_json(d.verdict);
  return j.dump(2) + "\n";
}

DiagnosisRecord parse_diagnosis(const std::string& text, const std::string& file) {
  const Json doc = parse_json(text, file);
  // Older schemas are read as the current one: what they lack stays empty.
  std::string schema = kDiagnosisSchema;
  if (doc.is_object() && doc.contains("schema"))
    for (const char* older : {kDiagnosisSchemaV1, kDiagnosisSchemaV2})
      if (doc["schema"] == older) schema = older;
  const bool v1 = schema == kDiagnosisSchemaV1;
  ObjectReader o(document_root(doc, file, schema.c_str(), "diagnosis"));
  DiagnosisRecord d;
  d.schema = o.required("schema").text();
  d.version = o.required("version").text();
  d.input = read_input(o.required("input"));
  d.settings = read_settings(o.required("settings"));
  d.gap = read_gap(o.required("gap"));
  for (const auto& s : o.required("stages").elements()) d.stages.push_back(read_stage(s));
  d.log_evidence_none = o.required("log_evidence_none").number();
  for (const auto& e : o.required("effects").elements()) d.effects.push_back(read_effect(e));
  d.verdict = read_verdict(o.required("verdict"), schema);
  if (v1) d.verdict.explanation = explanation_of_v1(d.verdict, d.effects);  // its one effect is its explanation
  d.schema = kDiagnosisSchema;
  o.finish();
  return d;
}

DiagnosisRecord read_diagnosis_file(const std::string& path) {
  return parse_diagnosis(read_bounded(path, kMaxDocumentBytes, "diagnosis"), path);
}

}  // namespace admitgen::io

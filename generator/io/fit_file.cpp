// SPDX-License-Identifier: MIT
#include "io/fit_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "io/json_fields.hpp"
#include "model/order.hpp"

#include <fmt/format.h>

namespace admitgen::io {
namespace {

// ---- writer ---------------------------------------------------------------------------------------

template <class T>
Json optional_json(const std::optional<T>& v) {
  return v ? Json(*v) : Json(nullptr);
}

Json parameters_json(const std::vector<FitParameter>& params) {
  Json out = Json::array();
  for (const auto& p : params)
    out.push_back({{"name", p.name},
                   {"mean", p.mean},
                   {"std", p.std},
                   {"ci95", {p.ci95_lo, p.ci95_hi}},
                   {"max_likelihood", p.max_likelihood}});
  return out;
}

Json input_json(const FitInput& in) {
  Json j{{"path", in.path},     {"sha256", in.sha256},     {"points", in.points}, {"f_min_hz", in.f_min_hz},
         {"f_max_hz", in.f_max_hz}, {"columns", in.columns}, {"quantity", in.quantity}};
  if (in.read_as) j["read_as"] = *in.read_as;
  j["rho_c"] = optional_json(in.rho_c);
  j["band"] = optional_json(in.band);
  return j;
}

Json settings_json(const FitSettingsRecord& s) {
  Json ranges = Json::object();
  for (const auto& [key, range] : s.prior_ranges) ranges[key] = range;
  Json priors{{"source", s.priors_source}, {"symmetry_reduced", s.symmetry_reduced}};
  if (s.residue_prior) priors["residues"] = *s.residue_prior;
  priors["ranges"] = ranges;
  Json sampler{{"method", s.sampler.method}, {"dlogz", s.sampler.dlogz}, {"max_iterations", s.sampler.max_iterations}};
  if (s.sampler.missed_mode_retries) sampler["missed_mode_retries"] = *s.sampler.missed_mode_retries;
  sampler["slices"] = s.sampler.slices ? Json(*s.sampler.slices) : Json("3 + dim");
  if (s.sampler.residues) sampler["residues"] = *s.sampler.residues;
  Json j{{"live", s.live},
         {"seed", s.seed},
         {"priors", priors},
         {"likelihood", s.likelihood},
         {"select", s.select},
         {"qmax", s.qmax},
         {"smax", s.smax},
         {"sampler", sampler}};
  if (s.passive) j["passive"] = *s.passive;
  if (s.grid_growth) j["grid_growth"] = *s.grid_growth;
  return j;
}

Json grid_json(const FitGrid& g) {
  Json j{{"qmax", g.qmax}, {"smax", g.smax}, {"steps", plain_texts(g.steps)}};
  if (g.edge) j["edge"] = plain_settings(*g.edge);
  return j;
}

Json passive_json(const FitPassiveEstimate& e) {
  Json j{{"poles_from", e.poles_from},
              {"sample_rank", e.sample_rank},
              {"residues", e.residues},
              {"parameters", numbers_by_name_json(e.parameters)},
              {"log_likelihood", e.log_likelihood},
              {"relative_rms_residual", e.relative_rms_residual},
              {"delta_log_likelihood_vs_best_sample", e.delta_log_likelihood_vs_best_sample},
              {"best_sample_relative_rms_residual", e.best_sample_relative_rms_residual},
              {"certified_passive", e.certified_passive},
              {"min_re_G", e.min_re_G},
              {"constraint_rounds", e.constraint_rounds}};
  if (e.sampled_poles_relative_rms_residual) j["sampled_poles_relative_rms_residual"] = *e.sampled_poles_relative_rms_residual;
  if (e.pole_search_steps) j["pole_search_steps"] = *e.pole_search_steps;
  if (e.passivity_cost) j["passivity_cost"] = *e.passivity_cost;
  return j;
}

Json model_json(const FitModel& m) {
  Json j{{"order", m.order}, {"Q", m.q}, {"S", m.s}};
  if (m.live) j["live"] = *m.live;
  j["log_evidence"] = m.log_evidence;
  j["log_evidence_error"] = m.log_evidence_error;
  j["max_log_likelihood"] = m.max_log_likelihood;
  j["information_nats"] = m.information_nats;
  j["likelihood_calls"] = m.likelihood_calls;
  j["iterations"] = m.iterations;
  j["stopped_by"] = m.stopped_by;
  if (m.seconds) j["seconds"] = *m.seconds;
  j["parameters"] = parameters_json(m.parameters);
  if (m.passive_estimate) j["passive_estimate"] = passive_json(*m.passive_estimate);
  if (m.log_passive_prior_fraction) j["log_passive_prior_fraction"] = *m.log_passive_prior_fraction;
  if (m.goodness_of_fit)
    j["goodness_of_fit"] = {{"estimate", m.goodness_of_fit->estimate},
                            {"relative_rms_residual", m.goodness_of_fit->relative_rms_residual},
                            {"max_abs_delta_alpha", m.goodness_of_fit->max_abs_delta_alpha}};
  if (m.sampler) j["sampler"] = *m.sampler;
  if (m.sampler_note) j["sampler_note"] = plain_settings(*m.sampler_note);
  return j;
}

Json predictive_json(const FitPredictive& p) {
  return Json{{"draws", p.draws},     {"quantiles", p.quantiles}, {"f_hz", p.f_hz},
              {"re_G", p.re_G},       {"im_G", p.im_G},           {"alpha", p.alpha}};
}

// ---- reader ---------------------------------------------------------------------------------------

std::vector<FitParameter> read_parameters(const Field& f) {
  std::vector<FitParameter> out;
  for (const auto& e : f.elements()) {
    ObjectReader o(e);
    FitParameter p;
    p.name = o.required("name").text();
    p.mean = o.required("mean").number();
    p.std = o.required("std").number();
    const auto ci = o.required("ci95").number_pair();
    p.ci95_lo = ci[0];
    p.ci95_hi = ci[1];
    p.max_likelihood = o.required("max_likelihood").number();
    o.finish();
    out.push_back(p);
  }
  return out;
}

FitInput read_input(const Field& f) {
  ObjectReader o(f);
  FitInput in;
  in.path = o.required("path").text();
  in.sha256 = o.required("sha256").text();
  in.points = o.required("points").integer();
  in.f_min_hz = o.required("f_min_hz").number();
  in.f_max_hz = o.required("f_max_hz").number();
  in.columns = o.required("columns").text();
  in.quantity = o.required("quantity").text();
  if (auto v = o.optional("read_as")) in.read_as = v->text();
  if (auto v = o.optional("rho_c"); v && !v->json().is_null()) in.rho_c = v->number();
  if (auto v = o.optional("band"); v && !v->json().is_null()) in.band = v->number_pair();
  o.finish();
  return in;
}

FitSamplerSettings read_sampler_settings(const Field& f) {
  ObjectReader o(f);
  FitSamplerSettings s;
  s.method = o.required("method").text();
  s.dlogz = o.required("dlogz").number();
  s.max_iterations = o.required("max_iterations").integer();
  if (auto v = o.optional("missed_mode_retries")) s.missed_mode_retries = v->integer();
  const Field slices = o.required("slices");
  if (slices.json().is_string()) {
    if (slices.text() != "3 + dim") slices.fail("expected a number of slices or \"3 + dim\"");
  } else {
    s.slices = slices.integer();
  }
  if (auto v = o.optional("residues")) s.residues = v->text();
  o.optional("truncation_tolerance_nats");  // written by versions with the residue box's correction; ignored
  o.finish();
  return s;
}

FitSettingsRecord read_settings(const Field& f) {
  ObjectReader o(f);
  FitSettingsRecord s;
  s.live = o.required("live").integer();
  s.seed = o.required("seed").unsigned_integer();
  {
    ObjectReader priors(o.required("priors"));
    s.priors_source = priors.required("source").text();
    s.symmetry_reduced = priors.required("symmetry_reduced").boolean();
    if (auto v = priors.optional("residues")) s.residue_prior = v->text();
    for (const auto& [key, range] : ObjectReader(priors.required("ranges")).members())
      s.prior_ranges.emplace_back(key, range.number_pair());
    priors.finish();
  }
  s.likelihood = o.required("likelihood").text();
  s.select = o.required("select").text();
  s.qmax = o.required("qmax").integer();
  s.smax = o.required("smax").integer();
  s.sampler = read_sampler_settings(o.required("sampler"));
  if (auto v = o.optional("passive")) s.passive = v->text();
  if (auto v = o.optional("grid_growth")) s.grid_growth = v->integer();
  o.finish();
  return s;
}

FitGrid read_grid(const Field& f) {
  ObjectReader o(f);
  FitGrid g;
  g.qmax = o.required("qmax").integer();
  g.smax = o.required("smax").integer();
  g.steps = o.required("steps").texts();
  if (auto v = o.optional("edge")) g.edge = v->text();
  o.finish();
  return g;
}

FitPassiveEstimate read_passive(const Field& f) {
  ObjectReader o(f);
  FitPassiveEstimate e;
  e.poles_from = o.required("poles_from").text();
  e.sample_rank = o.required("sample_rank").integer();
  e.residues = o.required("residues").text();
  e.parameters = o.required("parameters").numbers_by_name();
  e.log_likelihood = o.required("log_likelihood").number();
  e.relative_rms_residual = o.required("relative_rms_residual").number();
  e.delta_log_likelihood_vs_best_sample = o.required("delta_log_likelihood_vs_best_sample").number();
  e.best_sample_relative_rms_residual = o.required("best_sample_relative_rms_residual").number();
  e.certified_passive = o.required("certified_passive").boolean();
  e.min_re_G = o.required("min_re_G").number();
  e.constraint_rounds = o.required("constraint_rounds").integer();
  if (auto v = o.optional("sampled_poles_relative_rms_residual")) e.sampled_poles_relative_rms_residual = v->number();
  if (auto v = o.optional("pole_search_steps")) e.pole_search_steps = v->integer();
  if (auto v = o.optional("passivity_cost")) e.passivity_cost = v->text();
  o.finish();
  return e;
}

FitModel read_model(const Field& f) {
  ObjectReader o(f);
  FitModel m;
  const Field order = o.required("order");
  m.order = order.text();
  try {
    Order::parse(m.order);
  } catch (const InputError&) {
    order.fail("expected an order QxSy");
  }
  m.q = o.required("Q").integer();
  m.s = o.required("S").integer();
  if (auto v = o.optional("live")) m.live = v->integer();
  m.log_evidence = o.required("log_evidence").number();
  m.log_evidence_error = o.required("log_evidence_error").number();
  m.max_log_likelihood = o.required("max_log_likelihood").number();
  m.information_nats = o.required("information_nats").number();
  m.likelihood_calls = o.required("likelihood_calls").integer();
  m.iterations = o.required("iterations").integer();
  m.stopped_by = o.required("stopped_by").text();
  if (auto v = o.optional("seconds")) m.seconds = v->number();
  m.parameters = read_parameters(o.required("parameters"));
  if (auto v = o.optional("passive_estimate")) m.passive_estimate = read_passive(*v);
  if (auto v = o.optional("log_passive_prior_fraction")) m.log_passive_prior_fraction = v->number();
  if (auto v = o.optional("goodness_of_fit")) {
    ObjectReader g(*v);
    m.goodness_of_fit = FitGoodness{g.required("estimate").text(), g.required("relative_rms_residual").number(),
                                    g.required("max_abs_delta_alpha").number()};
    g.finish();
  }
  if (auto v = o.optional("sampler")) m.sampler = v->text();
  if (auto v = o.optional("sampler_note")) m.sampler_note = v->text();
  // Written by versions with the residue box's correction (docs/formats.md); read and ignored.
  for (const char* key : {"truncation_correction_nats", "truncation_correction_error_nats", "reweighted_ess_ratio",
                          "residue_draws_gibbs_weight"})
    o.optional(key);
  o.finish();
  return m;
}

std::array<std::vector<double>, 3> read_quantile_rows(const Field& f, std::size_t length) {
  const auto rows = f.elements();
  if (rows.size() != 3) f.fail("expected three quantile rows");
  std::array<std::vector<double>, 3> out;
  for (std::size_t i = 0; i < 3; ++i) {
    out[i] = rows[i].numbers();
    if (out[i].size() != length) rows[i].fail(fmt::format("expected {} values (one per f_hz)", length));
  }
  return out;
}

FitPredictive read_predictive(const Field& f) {
  ObjectReader o(f);
  FitPredictive p;
  p.draws = o.required("draws").integer();
  p.quantiles = o.required("quantiles").numbers();
  p.f_hz = o.required("f_hz").numbers();
  p.re_G = read_quantile_rows(o.required("re_G"), p.f_hz.size());
  p.im_G = read_quantile_rows(o.required("im_G"), p.f_hz.size());
  p.alpha = read_quantile_rows(o.required("alpha"), p.f_hz.size());
  o.finish();
  return p;
}

}  // namespace

std::string fit_text(const FitRecord& fit) {
  Json models = Json::array();
  for (const auto& m : fit.models) models.push_back(model_json(m));
  Json j{{"schema", fit.schema},
         {"version", fit.version},
         {"input", input_json(fit.input)},
         {"settings", settings_json(fit.settings)},
         {"models", models},
         {"bayes_factors_deciban", numbers_by_name_json(fit.bayes_factors_deciban)},
         {"bayes_factor_errors_deciban", numbers_by_name_json(fit.bayes_factor_errors_deciban)},
         {"selected", {{"order", fit.selected_order}, {"rule", fit.selected_rule}}},
         {"parameters", parameters_json(fit.parameters)}};
  if (fit.predictive) j["predictive"] = predictive_json(*fit.predictive);
  if (fit.warnings) j["warnings"] = plain_texts(*fit.warnings);
  if (fit.posterior) j["posterior"] = *fit.posterior;
  if (fit.grid) j["grid"] = grid_json(*fit.grid);
  return j.dump(2) + "\n";
}

bool is_json(const std::string& text) { return !Json::parse(text, nullptr, false).is_discarded(); }

FitRecord parse_fit(const std::string& text, const std::string& file) {
  const Json doc = parse_json(text, file);
  ObjectReader o(document_root(doc, file, kFitSchema, "fit"));
  FitRecord fit;
  fit.schema = o.required("schema").text();
  fit.version = o.required("version").text();
  fit.input = read_input(o.required("input"));
  fit.settings = read_settings(o.required("settings"));
  for (const auto& m : o.required("models").elements()) fit.models.push_back(read_model(m));
  fit.bayes_factors_deciban = o.required("bayes_factors_deciban").numbers_by_name();
  fit.bayes_factor_errors_deciban = o.required("bayes_factor_errors_deciban").numbers_by_name();
  {
    ObjectReader selected(o.required("selected"));
    const Field order = selected.required("order");
    fit.selected_order = order.text();
    fit.selected_rule = selected.required("rule").text();
    selected.finish();
    bool known = false;
    try {
      known = fit.model() != nullptr;
    } catch (const InputError&) {  // not an order at all
    }
    if (!known) order.fail("the selected order is not among the fitted models");
  }
  fit.parameters = read_parameters(o.required("parameters"));
  if (auto v = o.optional("predictive")) fit.predictive = read_predictive(*v);
  if (auto v = o.optional("warnings")) fit.warnings = v->texts();
  if (auto v = o.optional("posterior")) fit.posterior = v->text();
  if (auto v = o.optional("grid")) fit.grid = read_grid(*v);
  o.finish();
  return fit;
}

FitRecord read_fit_file(const std::string& path) {
  return parse_fit(read_bounded(path, kMaxDocumentBytes, "fit.json"), path);
}

}  // namespace admitgen::io

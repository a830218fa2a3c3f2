// SPDX-License-Identifier: MIT
#include "output/fit_json.hpp"

#include "core/version.hpp"
#include "selection/goodness_of_fit.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen {
namespace {

using Json = nlohmann::ordered_json;

Json to_json(const std::vector<ParameterSummary>& params) {
  Json out = Json::array();
  for (const auto& p : params)
    out.push_back({{"name", p.name},
                   {"mean", p.mean},
                   {"std", p.std},
                   {"ci95", {p.ci95_lo, p.ci95_hi}},
                   {"max_likelihood", p.max_likelihood}});
  return out;
}

Json to_json(const Eigen::ArrayXd& a) { return Json(std::vector<double>(a.data(), a.data() + a.size())); }

Json input_json(const Measurement& data, const ReadOptions& read) {
  Json in{{"path", data.path},
          {"sha256", data.sha256},
          {"points", data.size()},
          {"f_min_hz", data.f_hz[0]},
          {"f_max_hz", data.f_hz[data.size() - 1]},
          {"columns", read.columns ? read.columns->spec : "auto"},  // auto: see read_as
          {"quantity", data.quantity},
          {"read_as", data.read_as}};
  in["rho_c"] = read.rho_c ? Json(*read.rho_c) : Json(nullptr);
  in["band"] = read.band ? Json{read.band->lo_hz, read.band->hi_hz} : Json(nullptr);
  return in;
}

Json settings_json(const FitSettings& s, std::size_t n_points) {
  const int k = real_data_count(s.data_count, static_cast<Eigen::Index>(n_points));
  Json j{{"live", s.sampler.live},
              {"seed", s.sampler.seed},
              {"priors", {{"source", s.priors_origin}, {"symmetry_reduced", s.reduce_symmetry}, {"ranges", s.priors.to_json()}}},
              {"likelihood", fmt::format("{}; K = {}", describe(s.data_count), k)},
              {"select", s.rule.describe()},
              {"qmax", s.qmax},
              {"smax", s.smax},
              {"sampler", {{"method", "nested sampling, slice steps along whitened random directions"},
                           {"dlogz", s.sampler.dlogz},
                           {"max_iterations", s.sampler.max_iterations},
                           {"missed_mode_retries", s.missed_mode_retries},
                           {"slices", s.sampler.slices > 0 ? Json(s.sampler.slices) : Json("3 + dim")},
                           {"residues", s.sampler_kind == SamplerKind::poles
                                            ? "integrated analytically (poles sampled, box correction; full sampler "
                                              "where the correction is not accurate to the tolerance)"
                                            : "sampled"},
                           {"truncation_tolerance_nats", s.truncation_tolerance}}}};
  if (s.passive) j["passive"] = "prior truncated to passive models (Hamiltonian test); evidence under the renormalised prior";
  return j;
}

/// The passive estimate (docs/passivity.md): parameters by name, its fit and its certificate.
Json passive_json(const ModelResult& m) {
  const auto& e = m.passive;
  const auto names = m.order.parameter_names();
  Json params = Json::object();
  for (std::size_t i = 0; i < names.size(); ++i) params[names[i]] = e.theta[static_cast<Eigen::Index>(i)];
  return Json{{"poles_from", passivity::PassiveEstimate::kPolesFrom},
              {"sample_rank", e.candidate_rank},
              {"residues", e.changed ? "refitted: least squares to the data subject to Re G >= 0 at every frequency"
                                     : "those of the sample (already passive)"},
              {"parameters", params},
              {"log_likelihood", e.log_likelihood},
              {"relative_rms_residual", e.relative_rms_residual},
              {"delta_log_likelihood_vs_best_sample", e.log_likelihood - e.best_sample_log_likelihood},
              {"best_sample_relative_rms_residual", e.best_sample_relative_rms_residual},
              {"certified_passive", e.certified},
              {"min_re_G", e.min_re},
              {"constraint_rounds", e.rounds}};
}

Json model_json(const ModelResult& m, const Measurement& data) {
  Json j{{"order", m.order.name()},
              {"Q", m.order.q()},
              {"S", m.order.s()},
              {"live", m.live},
              {"log_evidence", m.run.log_z},
              {"log_evidence_error", m.run.log_z_error},
              {"max_log_likelihood", m.run.max_log_likelihood},
              {"information_nats", m.run.information},
              {"likelihood_calls", m.run.calls},
              {"iterations", m.run.iterations},
              {"stopped_by", m.run.stopped_by},
              {"parameters", to_json(m.parameters)},
              {"passive_estimate", passive_json(m)}};
  if (m.run.log_support_fraction != 0.0) j["log_passive_prior_fraction"] = m.run.log_support_fraction;
  const GoodnessOfFit g = goodness_of_fit(data, m);
  j["goodness_of_fit"] = {{"estimate", "max_likelihood"},
                          {"relative_rms_residual", g.relative_rms},
                          {"max_abs_delta_alpha", g.max_abs_delta_alpha}};
  j["sampler"] = m.sampler;  // "poles_analytic_residues" | "full" (selection/fit.hpp)
  if (!m.sampler_note.empty()) j["sampler_note"] = m.sampler_note;
  if (m.sampler != "full") {
    j["truncation_correction_nats"] = m.truncation_correction;
    j["truncation_correction_error_nats"] = m.truncation_correction_error;
    j["reweighted_ess_ratio"] = m.reweighted_ess_ratio;
    j["residue_draws_gibbs_weight"] = m.gibbs_weight;
  }
  return j;
}

Json predictive_json(const PredictiveBand& b) {
  return Json{{"draws", b.draws},
              {"quantiles", {0.025, 0.5, 0.975}},
              {"f_hz", to_json(b.f_hz)},
              {"re_G", {to_json(b.re_lo), to_json(b.re_median), to_json(b.re_hi)}},
              {"im_G", {to_json(b.im_lo), to_json(b.im_median), to_json(b.im_hi)}},
              {"alpha", {to_json(b.alpha_lo), to_json(b.alpha_median), to_json(b.alpha_hi)}}};
}

}  // namespace

Json fit_to_json(const Measurement& data, const ReadOptions& read, const FitSettings& settings, const FitResult& fit) {
  const ModelResult& chosen = fit.models[fit.selected];
  Json models = Json::array(), factors = Json::object(), errors = Json::object();
  for (const auto& m : fit.models) {
    models.push_back(model_json(m, data));
    factors[m.order.name()] = deciban(m.run.log_z, chosen.run.log_z);
    errors[m.order.name()] =
        &m == &chosen ? 0.0 : 10.0 / std::log(10.0) * std::hypot(m.run.log_z_error, chosen.run.log_z_error);
  }
  std::vector<std::string> warnings = data.warnings;  // the reader's (e.g. plausibility demoted to warnings)
  warnings.insert(warnings.end(), fit.warnings.begin(), fit.warnings.end());
  if (const auto poor = poor_fit_warning(chosen.order.name(), goodness_of_fit(data, chosen))) warnings.push_back(*poor);
  return Json{{"schema", "admitgen.fit/1"},
              {"version", kVersion},
              {"input", input_json(data, read)},
              {"settings", settings_json(settings, static_cast<std::size_t>(data.size()))},
              {"models", models},
              {"bayes_factors_deciban", factors},
              {"bayes_factor_errors_deciban", errors},
              {"selected", {{"order", chosen.order.name()}, {"rule", settings.rule.describe()}}},
              {"parameters", to_json(chosen.parameters)},
              {"predictive", predictive_json(fit.predictive)},
              {"warnings", warnings}};
}

}  // namespace admitgen

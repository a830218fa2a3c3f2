#include "output/fit_json.hpp"

#include "core/version.hpp"

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

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::admittance: return "admittance";
    case Quantity::impedance: return "impedance";
    case Quantity::reflection: return "reflection";
  }
  return "?";
}

Json input_json(const Measurement& data, const ReadOptions& read) {
  Json in{{"path", data.path},
          {"sha256", data.sha256},
          {"points", data.size()},
          {"f_min_hz", data.f_hz[0]},
          {"f_max_hz", data.f_hz[data.size() - 1]},
          {"columns", read.columns.spec},
          {"quantity", quantity_name(read.quantity)}};
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

Json model_json(const ModelResult& m) {
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
              {"seconds", m.seconds},
              {"parameters", to_json(m.parameters)}};
  if (m.run.log_support_fraction != 0.0) j["log_passive_prior_fraction"] = m.run.log_support_fraction;
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
    models.push_back(model_json(m));
    factors[m.order.name()] = deciban(m.run.log_z, chosen.run.log_z);
    errors[m.order.name()] =
        &m == &chosen ? 0.0 : 10.0 / std::log(10.0) * std::hypot(m.run.log_z_error, chosen.run.log_z_error);
  }
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
              {"warnings", fit.warnings}};
}

}  // namespace admitgen

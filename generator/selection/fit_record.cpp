// SPDX-License-Identifier: MIT
#include "selection/fit_record.hpp"

#include "core/version.hpp"
#include "inference/evidence.hpp"
#include "selection/goodness_of_fit.hpp"
#include "selection/prior_edge.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen {
namespace {

std::vector<FitParameter> parameters(const std::vector<ParameterSummary>& summaries) {
  std::vector<FitParameter> out;
  for (const auto& p : summaries) out.push_back({p.name, p.mean, p.std, p.ci95_lo, p.ci95_hi, p.max_likelihood});
  return out;
}

std::vector<double> values(const Eigen::ArrayXd& a) { return std::vector<double>(a.data(), a.data() + a.size()); }

FitInput input(const Measurement& data, const ReadOptions& read) {
  FitInput in;
  in.path = data.path;
  in.sha256 = data.sha256;
  in.points = data.size();
  in.f_min_hz = data.f_hz[0];
  in.f_max_hz = data.f_hz[data.size() - 1];
  in.columns = read.columns ? read.columns->spec : "auto";  // auto: see read_as
  in.quantity = data.quantity;
  in.read_as = data.read_as;
  in.rho_c = read.rho_c;
  if (read.band) in.band = std::array<double, 2>{read.band->lo_hz, read.band->hi_hz};
  return in;
}

FitSettingsRecord settings_record(const FitSettings& s, Eigen::Index n_points) {
  FitSettingsRecord r;
  r.residue_prior = s.priors.residues == ResiduePrior::gaussian
                        ? fmt::format("gaussian, zero mean, admittance scale s = {}; standard deviations s for G_inf, "
                                      "s*lambda_q for A_q, s*alpha_s for B_s and C_s",
                                      s.priors.admittance_scale)
                        : std::string("uniform over the ranges");
  r.live = s.sampler.live;
  r.seed = s.sampler.seed;
  r.priors_source = s.priors_origin;
  r.symmetry_reduced = s.reduce_symmetry;
  for (const auto& [key, range] : s.priors.named()) r.prior_ranges.push_back({key, {range.lo, range.hi}});
  r.likelihood = fmt::format("{}; K = {}", describe(s.data_count), real_data_count(s.data_count, n_points));
  r.select = s.rule.describe();
  r.qmax = s.qmax;
  r.smax = s.smax;
  r.sampler.method = order_sampler(s) == SamplerKind::poles
                         ? "nested sampling of the poles; draws from the live points' "
                           "bounding ellipsoid while they form one cluster and the draws cost fewer calls, the other "
                           "steps are slices along whitened random directions"
                         : "nested sampling, slice steps along whitened random directions";
  r.sampler.dlogz = s.sampler.stop_dlogz();
  r.sampler.max_iterations = s.sampler.max_iterations;
  r.sampler.missed_mode_retries = s.missed_mode_retries;
  r.sampler.runs = s.runs;
  if (s.sampler.slices > 0) r.sampler.slices = s.sampler.slices;
  r.sampler.residues = order_sampler(s) == SamplerKind::poles
                           ? "integrated exactly with the noise (poles sampled; residues and noise drawn from their "
                             "conditional)"
                           : "sampled";
  r.grid_growth = s.grid_growth;
  r.target = FitTarget{s.target.max_band_delta_alpha, std::nullopt, std::nullopt};
  if (s.target.max_relative_rms > 0.0) r.target->max_relative_rms = s.target.max_relative_rms;
  if (s.max_buffers > 0) r.target->max_buffers = s.max_buffers;
  if (s.passive) r.passive = "prior truncated to passive models (Hamiltonian test); evidence under the renormalised prior";
  return r;
}

/// The passive estimate (docs/passivity.md): parameters by name, its fit and its certificate.
FitPassiveEstimate passive_record(const ModelResult& m) {
  const auto& e = m.passive;
  FitPassiveEstimate r;
  r.poles_from = e.poles_searched ? passivity::PassiveEstimate::kPolesSearched : passivity::PassiveEstimate::kPolesFrom;
  r.sample_rank = e.candidate_rank;
  r.residues = e.changed ? "refitted: least squares to the data under the Gaussian residue prior (MAP) subject to Re G >= 0 at "
                           "every frequency"
                         : "those of the sample (already passive)";
  const auto names = m.order.parameter_names();
  for (std::size_t i = 0; i < names.size(); ++i) r.parameters.emplace_back(names[i], e.theta[static_cast<Eigen::Index>(i)]);
  r.log_likelihood = e.log_likelihood;
  r.relative_rms_residual = e.relative_rms_residual;
  r.delta_log_likelihood_vs_best_sample = e.log_likelihood - e.best_sample_log_likelihood;
  r.best_sample_relative_rms_residual = e.best_sample_relative_rms_residual;
  r.certified_passive = e.certified;
  r.min_re_G = e.min_re;
  r.constraint_rounds = e.rounds;
  if (e.poles_searched) {
    r.sampled_poles_relative_rms_residual = e.sampled_poles_relative_rms_residual;
    r.pole_search_steps = e.search_steps;
  }
  if (!e.cost_reason.empty()) r.passivity_cost = e.cost_reason;
  r.passive_bound_relative_rms_residual = e.passive_bound_relative_rms_residual;
  r.conditioning = e.conditioning;
  r.best_sample_conditioning = e.best_sample_conditioning;
  if (!e.conditioning_tradeoff.empty()) r.conditioning_tradeoff = e.conditioning_tradeoff;
  return r;
}

FitModel model_record(const ModelResult& m, const Measurement& data) {
  FitModel r;
  r.order = m.order.name();
  r.q = m.order.q();
  r.s = m.order.s();
  r.live = m.live;
  r.log_evidence = m.run.log_z;
  r.log_evidence_error = m.run.log_z_error;
  r.max_log_likelihood = m.run.max_log_likelihood;
  r.information_nats = m.run.information;
  r.likelihood_calls = m.run.calls;
  r.iterations = m.run.iterations;
  r.stopped_by = m.run.stopped_by;
  r.parameters = parameters(m.parameters);
  r.passive_estimate = passive_record(m);
  if (m.run.log_support_fraction != 0.0) r.log_passive_prior_fraction = m.run.log_support_fraction;
  const GoodnessOfFit g = goodness_of_fit(data, m);
  r.goodness_of_fit = FitGoodness{"max_likelihood", g.relative_rms, g.max_abs_delta_alpha};
  if (m.accuracy)
    r.accuracy = FitAccuracy{m.order.buffers(), m.accuracy->relative_rms, m.accuracy->max_band_delta_alpha,
                             m.accuracy->worst_band_hz, m.accuracy->meets, m.passive.conditioning};
  r.sampler = m.sampler;  // "poles_analytic_residues" | "full" (selection/fit.hpp)
  if (!m.sampler_note.empty()) r.sampler_note = m.sampler_note;
  return r;
}

FitPredictive predictive_record(const PredictiveBand& b) {
  FitPredictive r;
  r.draws = b.draws;
  r.quantiles = {0.025, 0.5, 0.975};
  r.f_hz = values(b.f_hz);
  r.re_G = {values(b.re_lo), values(b.re_median), values(b.re_hi)};
  r.im_G = {values(b.im_lo), values(b.im_median), values(b.im_hi)};
  r.alpha = {values(b.alpha_lo), values(b.alpha_median), values(b.alpha_hi)};
  return r;
}

}  // namespace

/// fit.json's "log_evidence_error": what each model's error of ln Z is (docs/method.md, "Model selection").
std::string log_evidence_error_meaning(int runs) {
  if (runs > 1)
    return fmt::format("from the scatter of {} independent runs per order where it exceeds sqrt(H/n)", runs);
  return "sqrt(H/n) of one run, a lower bound: on real data the seed scatter of ln Z is 2-15 times larger; "
         "two independent runs per order (runs = 2) measure it";
}

FitRecord fit_record(const Measurement& data, const ReadOptions& read, const FitSettings& given, const FitResult& fit) {
  const FitSettings settings = with_band_priors(given, data);
  const ModelResult& chosen = fit.models[fit.selected];
  FitRecord r;
  r.version = kVersion;
  r.input = input(data, read);
  r.settings = settings_record(settings, data.size());
  for (const auto& m : fit.models) {
    r.models.push_back(model_record(m, data));
    r.bayes_factors_deciban.emplace_back(m.order.name(), deciban(m.run.log_z, chosen.run.log_z));
    r.bayes_factor_errors_deciban.emplace_back(
        m.order.name(),
        &m == &chosen ? 0.0 : 10.0 / std::log(10.0) * std::hypot(m.run.log_z_error, chosen.run.log_z_error));
  }
  r.selected_order = chosen.order.name();
  r.selected_rule = settings.rule.describe();
  r.parameters = parameters(chosen.parameters);
  r.log_evidence_error_meaning = log_evidence_error_meaning(settings.runs);
  r.predictive = predictive_record(fit.predictive);
  std::vector<std::string> warnings = data.warnings;  // the reader's (e.g. plausibility demoted to warnings)
  warnings.insert(warnings.end(), fit.warnings.begin(), fit.warnings.end());
  if (const auto poor = poor_fit_warning(chosen.order.name(), goodness_of_fit(data, chosen))) warnings.push_back(*poor);
  if (const auto edge = prior_edge_warning(chosen, settings.priors)) warnings.push_back(*edge);
  r.warnings = warnings;
  if (!fit.notes.empty()) r.notes = fit.notes;
  if (!fit.grid.steps.empty() || !fit.grid.edge.empty()) {
    FitGrid g{fit.grid.qmax, fit.grid.smax, fit.grid.steps, {}};
    if (!fit.grid.edge.empty()) g.edge = fit.grid.edge;
    r.grid = g;
  }
  return r;
}

}  // namespace admitgen

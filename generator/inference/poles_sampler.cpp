// SPDX-License-Identifier: MIT
#include "inference/poles_sampler.hpp"

#include "core/rng.hpp"
#include "inference/pole_space.hpp"
#include "inference/posterior.hpp"
#include "inference/residue_draws.hpp"
#include "inference/residue_marginal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

/// The analytic case (no poles): one "point" of the pole space carries all the evidence.
NestedRun analytic_run(const ResidueMarginal& marginal, int draws) {
  NestedRun run;
  run.dim = 0;
  const double log_l = marginal(nullptr);
  for (int i = 0; i < draws; ++i) {
    run.log_likelihood.push_back(log_l);
    run.log_weight.push_back(log_l - std::log(static_cast<double>(draws)));
  }
  run.log_z = log_l;
  run.calls = 1;
  run.stopped_by = "analytic";
  return run;
}

/// The poles as a model (inference/model.hpp): the residue-marginal likelihood over ψ with the fold.
/// Holds references: `transform` and `marginal` outlive the run.
Model pole_model(const Order& order, const PoleTransform& transform, const ResidueMarginal& marginal) {
  const std::vector<std::string> all = order.parameter_names();
  std::vector<std::string> names;
  for (int i : pole_indices(order)) names.push_back(all[static_cast<std::size_t>(i)]);
  return Model{std::move(names), [&transform](const double* u, double* psi) { transform(u, psi); },
               [&marginal](const double* psi) { return marginal(psi); }, [&transform](double* u) { transform.fold(u); }};
}

}  // namespace

PolesRun run_poles_sampler(const Measurement& data, const Order& order, const PriorRanges& priors,
                           bool reduce_symmetry, DataCount count, const NestedSettings& settings,
                           std::uint64_t draw_seed, const NestedProgressFn& progress) {
  const PoleTransform transform(order, priors, reduce_symmetry);
  const ResidueMarginal marginal(data, order, count, priors);
  const int dim = transform.dim();
  const NestedRun poles =
      dim == 0 ? analytic_run(marginal, settings.live)
               : run_nested_sampling(pole_model(order, transform, marginal), settings, progress);

  PolesRun out;
  NestedRun& run = out.run;
  run = poles;
  run.dim = order.dim();
  run.samples.assign(poles.size() * static_cast<std::size_t>(order.dim()), 0.0);
  const Likelihood likelihood(data, order, count);
  const Eigen::ArrayXd weight = posterior_weights(poles);
  Rng rng(draw_seed);
  double best_profile = -std::numeric_limits<double>::infinity();
  std::vector<double> best_theta;
  Eigen::ArrayXd rho = Eigen::ArrayXd::Ones(weight.size());
  double correction_variance = 0.0;  // Σ p_i² Var(ρ_i)
  // First pass: which points need the box estimate, and their share a_i = p_i/√P̃ of the draw budget
  // (minimising Σ p_i² Var(ρ_i) ≈ Σ p_i²/(m_i P̃) under Σ m_i = budget gives m_i ∝ p_i/√P̃).
  std::vector<double> share(poles.size(), 0.0);
  double share_sum = 0.0, corrected = 0.0;
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const ResidueConditional& c = marginal.conditional(dim == 0 ? nullptr : poles.point(i));
    if (c.valid && -std::expm1(c.log_p_lo - c.log_p_up) > 1e-9) {
      share[i] = std::exp(std::log(weight[static_cast<Eigen::Index>(i)]) - 0.5 * c.log_p_sampled);  // P̃ may underflow
      share_sum += share[i];
      corrected += 1.0;
    }
  }
  const double budget = std::min(kBoxDrawBudget, kBoxDrawsPerPoint * corrected);
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const Eigen::Index ii = static_cast<Eigen::Index>(i);
    const double* psi = dim == 0 ? nullptr : poles.point(i);
    const ResidueConditional& c = marginal.conditional(psi);
    double* theta = run.samples.data() + i * static_cast<std::size_t>(order.dim());
    if (!c.valid) {  // a numerically singular M (ln L = −∞): never a live or weighted point
      rho[ii] = 0.0;
      continue;
    }
    const Eigen::VectorXd &lo = marginal.box_lo(), &hi = marginal.box_hi();
    Eigen::VectorXd r;
    if (-std::expm1(c.log_p_lo - c.log_p_up) <= 1e-9) {
      ResidueDrawMethod method;
      r = draw_residues(c, lo, hi, rng, method);
      if (method == ResidueDrawMethod::gibbs) out.gibbs_weight += weight[ii];
    } else {
      // P̂ = h/m (unbiased for any m ≥ 1); the first draw inside the box is an exact draw of the
      // truncated t. m_i from the budget shares above, at most kMaxBoxDraws.
      const double wanted = share_sum > 0.0 ? budget * share[i] / share_sum : 1.0;
      const long m = std::clamp(static_cast<long>(std::ceil(std::min(wanted, 1e12))), 1L, kMaxBoxDraws);
      long hits = 0;
      for (long d = 0; d < m; ++d) {
        Eigen::VectorXd x = untruncated_residue_draw(c, rng);
        if (in_residue_box(x, lo, hi) && hits++ == 0) r = std::move(x);
      }
      const double md = static_cast<double>(m), p_hat = static_cast<double>(hits) / md;
      rho[ii] = hits == 0 ? 0.0 : std::exp(std::log(p_hat) - c.log_p_sampled);
      // Var(P̂) = P(1 − P)/m with P estimated by min(p̃, P̃), p̃ = (h + 1)/(m + 2): h = 0 or h = m does
      // not claim zero variance, and P_box ≤ P̃ (the slab bound, docs/method.md) caps it. In logs: P̃ may
      // underflow where the t lies far outside the box (such points carry no weight).
      const double log_p_tilde = std::min(std::log((hits + 1.0) / (md + 2.0)), c.log_p_sampled);
      correction_variance += std::exp(2.0 * (std::log(weight[ii]) - c.log_p_sampled) + log_p_tilde) *
                             -std::expm1(log_p_tilde) / md;
      if (hits == 0) r = c.mean.cwiseMax(lo).cwiseMin(hi);  // weight 0: any admissible θ will do
    }
    assemble_theta(order, psi, r, theta);
    run.log_likelihood[i] = likelihood(theta);
    // Profile likelihood (r = r̂) where r̂ is admissible: the best of these is the run's best θ.
    const double profile = -std::log(c.s_min);
    if (profile > best_profile && in_residue_box(c.mean, lo, hi)) {
      best_profile = profile;
      best_theta.assign(static_cast<std::size_t>(order.dim()), 0.0);
      assemble_theta(order, psi, c.mean, best_theta.data());
    }
  }
  const double mean_rho = (weight * rho).sum();
  out.truncation_correction = std::log(mean_rho);
  out.truncation_correction_error = std::sqrt(correction_variance) / mean_rho;
  if (mean_rho > 0.0) {
    out.reweighted_ess_ratio = effective_sample_size(weight * rho) / effective_sample_size(weight);
    for (std::size_t i = 0; i < poles.size(); ++i) run.log_weight[i] += std::log(rho[static_cast<Eigen::Index>(i)]);
    run.log_z += out.truncation_correction;
    run.log_z_error = std::hypot(run.log_z_error, out.truncation_correction_error);
  } else {
    out.reweighted_ess_ratio = 0.0;
  }
  if (!best_theta.empty()) {
    run.samples.insert(run.samples.end(), best_theta.begin(), best_theta.end());
    run.log_likelihood.push_back(likelihood(best_theta.data()));
    run.log_weight.push_back(-std::numeric_limits<double>::infinity());
  }
  run.max_log_likelihood = *std::max_element(run.log_likelihood.begin(), run.log_likelihood.end());
  return out;
}

}  // namespace admitgen

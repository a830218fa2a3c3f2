// SPDX-License-Identifier: MIT
#include "inference/poles_sampler.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "inference/pole_space.hpp"
#include "inference/posterior.hpp"
#include "inference/residue_evidence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

/// The analytic case (no poles): one "point" of the pole space carries all the evidence.
NestedRun analytic_run(const ResidueEvidence& evidence, int draws) {
  NestedRun run;
  run.dim = 0;
  const double log_l = evidence(nullptr);
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
/// Holds references: `transform` and `evidence` outlive the run.
Model pole_model(const Order& order, const PoleTransform& transform, const ResidueEvidence& evidence) {
  const std::vector<std::string> all = order.parameter_names();
  std::vector<std::string> names;
  for (int i : pole_indices(order)) names.push_back(all[static_cast<std::size_t>(i)]);
  return Model{std::move(names), [&transform](const double* u, double* psi) { transform(u, psi); },
               [&evidence](const double* psi) { return evidence(psi); }, [&transform](double* u) { transform.fold(u); }};
}

}  // namespace

NestedRun run_poles_sampler(const Measurement& data, const Order& order, const PriorRanges& priors,
                            bool reduce_symmetry, DataCount count, const NestedSettings& settings,
                            std::uint64_t draw_seed, const NestedProgressFn& progress) {
  ADMITGEN_ENSURE(priors.residues == ResiduePrior::gaussian, "the pole sampler needs the Gaussian residue prior");
  const PoleTransform transform(order, priors, reduce_symmetry);
  const ResidueEvidence evidence(data, order, count, priors.admittance_scale);
  const int dim = transform.dim();
  // The pole space has few dimensions (Q + 2S), where draws from bounding ellipsoids replace slice chains
  // at a fraction of the calls (inference/ellipsoid_union.hpp).
  NestedSettings pole_settings = settings;
  pole_settings.ellipsoid_draws = true;
  const NestedRun poles = dim == 0 ? analytic_run(evidence, settings.live)
                                   : run_nested_sampling(pole_model(order, transform, evidence), pole_settings, progress);

  NestedRun run = poles;
  run.dim = order.dim();
  run.sampled_log_likelihood = poles.log_likelihood;
  run.samples.assign(poles.size() * static_cast<std::size_t>(order.dim()), 0.0);
  const Likelihood likelihood(data, order, count);
  const Eigen::ArrayXd weight = posterior_weights(poles);
  Rng rng(draw_seed);
  // The run's best fit: of every sampled ψ, the one whose least-squares residues leave the smallest residual
  // S₀ (the highest ln L with residues free). The marginal's own peak is a different ψ wherever the prior
  // shrinks residues, as it does for a spare pair that could fit noise with large ones; the best fit is
  // what the missed-mode checks compare across orders (docs/method.md, "Model selection").
  double best = std::numeric_limits<double>::infinity(), best_marginal = best;
  std::vector<double> best_theta;
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const double* psi = dim == 0 ? nullptr : poles.point(i);
    double* theta = run.samples.data() + i * static_cast<std::size_t>(order.dim());
    const ResiduePosterior& c = evidence.posterior(psi);
    if (!c.valid) {  // never a live or weighted point (ln L = −∞ there)
      run.log_likelihood[i] = -std::numeric_limits<double>::infinity();
      continue;
    }
    if (c.s0 < best) {
      best = c.s0;
      best_marginal = c.log_evidence;
      best_theta.assign(static_cast<std::size_t>(order.dim()), 0.0);
      assemble_theta(order, psi, least_squares_residues(c), best_theta.data());
    }
    // Points whose posterior share is below kNegligibleShare/n (together at most kNegligibleShare of the posterior:
    // early dead points) keep their least-squares residues instead of a draw; no summary can see them.
    const bool negligible = weight[static_cast<Eigen::Index>(i)] < kNegligibleShare / static_cast<double>(poles.size());
    assemble_theta(order, psi, negligible ? least_squares_residues(c) : draw_residues(c, rng), theta);
    run.log_likelihood[i] = likelihood(theta);
  }
  if (!best_theta.empty()) {
    run.samples.insert(run.samples.end(), best_theta.begin(), best_theta.end());
    run.log_likelihood.push_back(likelihood(best_theta.data()));
    run.sampled_log_likelihood.push_back(best_marginal);
    run.log_weight.push_back(-std::numeric_limits<double>::infinity());
  }
  run.max_log_likelihood = *std::max_element(run.log_likelihood.begin(), run.log_likelihood.end());
  return run;
}

}  // namespace admitgen

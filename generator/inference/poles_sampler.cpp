// SPDX-License-Identifier: MIT
#include "inference/poles_sampler.hpp"

#include "core/rng.hpp"
#include "inference/evidence.hpp"
#include "inference/pole_space.hpp"
#include "inference/posterior.hpp"
#include "inference/residue_draws.hpp"
#include "inference/residue_marginal.hpp"

#include <fmt/format.h>

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

/// The poles with the box mass as coordinates (docs/method.md, "Sampling the box mass"): θ_ext = (ψ, u_W,
/// u_1 … u_p), ln L_ext = ln L_untruncated(ψ) + ln of the GHK replicate made from W = F⁻¹_χ²(u_W) and
/// u_1 … u_p (BoxMassSimulator::log_replicate), whose integral over the u cube is P_box(ψ). ψ is folded to
/// its canonical copy inside the transform, so L_ext is invariant under the fold of the pole coordinates
/// (the replicate's coordinate order follows ψ).
struct BoxCoordinates {
  const Order& order;
  const PoleTransform& transform;
  const ResidueMarginal& marginal;
  int dim;
  std::vector<double> u_poles;

  Model model() {
    std::vector<std::string> names = pole_model(order, transform, marginal).parameter_names;
    names.emplace_back("box_w");
    for (int k = 1; k < static_cast<int>(marginal.box_lo().size()) + 1; ++k) names.push_back(fmt::format("box_u{}", k));
    return Model{std::move(names),
                 [this](const double* u, double* theta) {
                   u_poles.assign(u, u + dim);
                   transform.fold(u_poles.data());
                   transform(u_poles.data(), theta);
                   std::copy(u + dim, u + dim + 1 + marginal.box_lo().size(), theta + dim);
                 },
                 [this](const double* theta) { return log_likelihood(theta); },
                 [this](double* u) { transform.fold(u); }};
  }

  /// ln of the replicate that the box coordinates of θ_ext make for the conditional c of its poles (and the
  /// deviation r − r̂ it draws, when asked).
  double log_replicate(const double* theta, const ResidueConditional& c, Eigen::VectorXd* deviation) const {
    BoxMassSimulator simulator(c, marginal.box_lo(), marginal.box_hi());
    return simulator.log_replicate(chi_square_quantile(c.nu, theta[dim]), theta + dim + 1, deviation);
  }

  double log_likelihood(const double* theta) const {
    const ResidueConditional& c = marginal.untruncated(theta);
    if (!c.valid) return -std::numeric_limits<double>::infinity();
    return c.log_marginal + log_replicate(theta, c, nullptr);
  }

  /// The residues a point of the run stands for, c the conditional of its poles (clamped to the box
  /// against rounding).
  Eigen::VectorXd residues(const double* theta, const ResidueConditional& c) const {
    Eigen::VectorXd deviation;
    log_replicate(theta, c, &deviation);
    return (c.mean + deviation).cwiseMax(marginal.box_lo()).cwiseMin(marginal.box_hi());
  }
};

/// The full-θ run made from a pole run: the same points and weights, each row θ = (ψ, r) with its ln L,
/// and one extra point of zero weight at the end, the poles of the highest profile likelihood with their
/// least-squares residues r̂ where r̂ is admissible (PolesRun::run).
class FullThetaRun {
 public:
  FullThetaRun(const Measurement& data, const Order& order, DataCount count, const NestedRun& poles, NestedRun& run)
      : order_(order), likelihood_(data, order, count), run_(run) {
    run_ = poles;
    run_.dim = order.dim();
    run_.samples.assign(poles.size() * static_cast<std::size_t>(order.dim()), 0.0);
  }

  /// Point i: θ = (ψ, r); (ψ, r̂) is offered as the run's best θ (c the conditional of ψ).
  void set(std::size_t i, const double* psi, const Eigen::VectorXd& r, const ResidueConditional& c,
           const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
    double* theta = run_.samples.data() + i * static_cast<std::size_t>(order_.dim());
    assemble_theta(order_, psi, r, theta);
    run_.log_likelihood[i] = likelihood_(theta);
    const double profile = -std::log(c.s_min);
    if (profile > best_profile_ && in_residue_box(c.mean, lo, hi)) {
      best_profile_ = profile;
      best_theta_.assign(static_cast<std::size_t>(order_.dim()), 0.0);
      assemble_theta(order_, psi, c.mean, best_theta_.data());
    }
  }

  /// Appends the best θ and sets max_log_likelihood.
  void finish() {
    if (!best_theta_.empty()) {
      run_.samples.insert(run_.samples.end(), best_theta_.begin(), best_theta_.end());
      run_.log_likelihood.push_back(likelihood_(best_theta_.data()));
      run_.log_weight.push_back(-std::numeric_limits<double>::infinity());
    }
    run_.max_log_likelihood = *std::max_element(run_.log_likelihood.begin(), run_.log_likelihood.end());
  }

 private:
  const Order& order_;
  const Likelihood likelihood_;
  NestedRun& run_;
  double best_profile_ = -std::numeric_limits<double>::infinity();
  std::vector<double> best_theta_;
};

/// The complete posterior of a run with the box mass sampled: every point's residues come from its own
/// coordinates and its weight is already exact (no correction).
void complete_box_sampled(const Measurement& data, const Order& order, DataCount count, const BoxCoordinates& box,
                          const NestedRun& poles, PolesRun& out) {
  FullThetaRun full(data, order, count, poles, out.run);
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const double* point = poles.point(i);
    const ResidueConditional& c = box.marginal.untruncated(point);
    full.set(i, point, box.residues(point, c), c, box.marginal.box_lo(), box.marginal.box_hi());
  }
  full.finish();
}

}  // namespace

PolesRun run_poles_sampler(const Measurement& data, const Order& order, const PriorRanges& priors,
                           bool reduce_symmetry, DataCount count, const NestedSettings& settings,
                           std::uint64_t draw_seed, const NestedProgressFn& progress, BoxMassMethod box_mass) {
  const PoleTransform transform(order, priors, reduce_symmetry);
  const ResidueMarginal marginal(data, order, count, priors);
  const int dim = transform.dim();
  if (box_mass == BoxMassMethod::sampled && dim > 0) {
    BoxCoordinates box{order, transform, marginal, dim, {}};
    PolesRun out;
    out.box_mass = BoxMassMethod::sampled;
    complete_box_sampled(data, order, count, box, run_nested_sampling(box.model(), settings, progress), out);
    return out;
  }
  // The pole space has few dimensions (Q + 2S), where draws from bounding ellipsoids replace slice chains
  // at a fraction of the calls (inference/ellipsoid_union.hpp). Not with the box mass as coordinates
  // (p + 1 more): there the draws land where calls cost more, and the reference file's Q3S3 took twice as
  // long with them.
  NestedSettings pole_settings = settings;
  pole_settings.ellipsoid_draws = true;
  const NestedRun poles =
      dim == 0 ? analytic_run(marginal, settings.live)
               : run_nested_sampling(pole_model(order, transform, marginal), pole_settings, progress);

  PolesRun out;
  NestedRun& run = out.run;
  FullThetaRun full(data, order, count, poles, run);
  const Eigen::ArrayXd weight = posterior_weights(poles);
  Rng rng(draw_seed);
  Eigen::ArrayXd rho = Eigen::ArrayXd::Ones(weight.size());
  // ln Σ p_i² Var(ρ_i), accumulated in logs: where P̂ ≪ P̃ throughout, its terms underflow in linear terms.
  double log_correction_variance = -std::numeric_limits<double>::infinity();
  // First pass: which points need the box estimate, and their share of the draw budget. With GHK the
  // relative variance of P̂ is of order one whatever P_box (Var(ρ_i) ≈ κ ρ_i²/m_i), so minimising
  // Σ p_i² κ/m_i under Σ m_i = budget gives m_i ∝ p_i.
  // Each point's conditional is solved once, here, and kept for the second pass.
  std::vector<double> share(poles.size(), 0.0);
  std::vector<ResidueConditional> conditionals;
  conditionals.reserve(poles.size());
  double share_sum = 0.0, corrected = 0.0;
  for (std::size_t i = 0; i < poles.size(); ++i) {
    conditionals.push_back(marginal.conditional(dim == 0 ? nullptr : poles.point(i)));
    const ResidueConditional& c = conditionals.back();
    if (c.valid && -std::expm1(c.log_p_lo - c.log_p_up) > 1e-9) {
      share[i] = weight[static_cast<Eigen::Index>(i)];
      share_sum += share[i];
      corrected += 1.0;
    }
  }
  const double budget = std::min(kBoxDrawBudget, kBoxDrawsPerPoint * corrected);
  for (std::size_t i = 0; i < poles.size(); ++i) {
    const Eigen::Index ii = static_cast<Eigen::Index>(i);
    const double* psi = dim == 0 ? nullptr : poles.point(i);
    const ResidueConditional& c = conditionals[i];
    if (!c.valid) {  // a numerically singular M (ln L = −∞): never a live or weighted point
      rho[ii] = 0.0;
      run.log_likelihood[i] = -std::numeric_limits<double>::infinity();  // nor the best sample
      continue;
    }
    const Eigen::VectorXd &lo = marginal.box_lo(), &hi = marginal.box_hi();
    Eigen::VectorXd r;
    // Points whose posterior share is below kNegligibleShare/n (together at most kNegligibleShare of the
    // posterior: early dead points, where the box mass is tiny and draws would need the Gibbs chain) keep
    // r̂ clamped to the box instead of a draw; no summary can see them.
    const bool negligible = weight[ii] < kNegligibleShare / static_cast<double>(poles.size());
    const bool box_mass_known = -std::expm1(c.log_p_lo - c.log_p_up) <= 1e-9;
    if (negligible && box_mass_known) {
      r = c.mean.cwiseMax(lo).cwiseMin(hi);
    } else if (box_mass_known) {
      ResidueDrawMethod method;
      r = draw_residues(c, lo, hi, rng, method);
      if (method == ResidueDrawMethod::gibbs) out.gibbs_weight += weight[ii];
    } else {
      // P̂: the mean of m GHK replicates (unbiased; inference/residue_draws.hpp), m_i from
      // the budget shares above; its variance from the replicates' sample variance.
      const double wanted = share_sum > 0.0 ? budget * share[i] / share_sum : 1.0;
      const long m = std::clamp(static_cast<long>(std::ceil(std::min(wanted, 1e12))), kMinBoxDraws, kMaxBoxDraws);
      const BoxMassEstimate estimate = estimate_box_mass(c, lo, hi, m, rng);
      const double md = static_cast<double>(m), p_hat = estimate.mean, sample_variance = estimate.sample_variance;
      rho[ii] = p_hat > 0.0 ? std::exp(std::log(p_hat) - c.log_p_sampled) : 0.0;
      // Var(ρ_i) = Var(P̂)/P̃² (in logs: P̃ may underflow where the t lies far outside the box).
      if (sample_variance > 0.0)
        log_correction_variance = log_add_exp(
            log_correction_variance, 2.0 * (std::log(weight[ii]) - c.log_p_sampled) + std::log(sample_variance / md));
      if (p_hat > 0.0 && !negligible) {
        ResidueDrawMethod method;
        r = draw_residues(c, lo, hi, rng, method);
        if (method == ResidueDrawMethod::gibbs) out.gibbs_weight += weight[ii];
      } else {
        r = c.mean.cwiseMax(lo).cwiseMin(hi);  // weight 0: any admissible θ will do
      }
    }
    full.set(i, psi, r, c, lo, hi);
  }
  const double mean_rho = (weight * rho).sum();
  out.truncation_correction = std::log(mean_rho);
  out.truncation_correction_error = std::exp(0.5 * log_correction_variance - std::log(mean_rho));
  if (mean_rho > 0.0) {
    // Scaled to a largest weight of 1 first: where P̂ ≪ P̃ everywhere (corrections of hundreds of nats) the
    // squares of weight·ρ underflow.
    const Eigen::ArrayXd reweighted = weight * rho;
    out.reweighted_ess_ratio = effective_sample_size(reweighted / reweighted.maxCoeff()) / effective_sample_size(weight);
    for (std::size_t i = 0; i < poles.size(); ++i) run.log_weight[i] += std::log(rho[static_cast<Eigen::Index>(i)]);
    run.log_z += out.truncation_correction;
    // The reweighted points carry the evidence with fewer effective samples: the sampling error √(H/n)
    // grows as for n·ratio points (a conservative allowance; docs/method.md, "Tolerance and fallback").
    run.log_z_error = std::hypot(run.log_z_error / std::sqrt(std::min(out.reweighted_ess_ratio, 1.0)),
                                 out.truncation_correction_error);
  } else {
    out.reweighted_ess_ratio = 0.0;
  }
  full.finish();
  return out;
}

}  // namespace admitgen

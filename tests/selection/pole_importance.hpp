// SPDX-License-Identifier: MIT
// An importance-sampling estimate of an order's evidence over the poles, with no nested sampling:
// Z = E_q[L(ψ) π(ψ)/q(ψ)], L(ψ) the likelihood of the poles alone under the Gaussian residue prior, the residues
// and the noise σ integrated out exactly (inference/residue_evidence.hpp; docs/method.md, "The closed-form
// marginal"). That is the integrand the pole sampler explores (docs/method.md, "Sampling the poles only"), so an
// error in its exploration or in its evidence accounting shows up against this estimate; L itself is checked
// against brute-force integration over r and σ in tests/inference/test_residue_evidence.cpp.
//
// The proposal q is built from posterior samples of any runs (both samplers, so a mode either found is covered):
// a mixture of multivariate t_5 kernels centred on K resampled posterior points of each run, with covariance
// h²Σ_r (Σ_r that run's posterior covariance, h Silverman's bandwidth), plus a defensive t_3(mean_r, 4Σ_r) per
// run with weight 0.2 in all. q only sets the variance; the estimate is unbiased for any q that covers the
// posterior. Its error is the sample standard error of the mean of the ratios.
//
// The integral runs over the fundamental domain D of the order's symmetries, D = {λ ascending, β ≥ 0, pairs
// ascending in β} (model/order.hpp; the form fit.json reports, fold_to_reduced): L is invariant under the
// Q! S! 2^S relabellings, so with the poles uniform over the ranges of `priors` (volume V_ψ),
// Z = Q! S! 2^S ∫_D L(ψ)/V_ψ dψ. This does not use the sampler's own fold.
#pragma once

#include "core/rng.hpp"
#include "inference/evidence.hpp"
#include "inference/pole_space.hpp"
#include "inference/posterior.hpp"
#include "inference/residue_evidence.hpp"
#include "selection/fit.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

namespace admitgen::test {

struct ImportanceEstimate {
  double log_z = 0.0, error = 0.0;
  double ess = 0.0;  ///< Kish effective sample size of the ratios
};

/// A χ²_ν draw for integer ν: the sum of ν squared standard normals.
inline double chi_square_draw(int nu, Rng& rng) {
  double w = 0.0;
  for (int i = 0; i < nu; ++i) {
    const double g = rng.normal();
    w += g * g;
  }
  return w;
}

/// ln L(ψ) (ResidueEvidence, two real data per point, the admittance scale of `priors`), −∞ where the poles
/// lie outside the model's domain.
inline double pole_log_evidence(const ResidueEvidence& evidence, const double* psi) {
  const ResiduePosterior& c = evidence.posterior(psi);
  return c.valid ? c.log_evidence : -std::numeric_limits<double>::infinity();
}

/// ln of the prior density of the poles on D: ln(Q! S! 2^S / V_ψ), V_ψ = |λ|^Q (|α| |β|)^S over the ranges of
/// `priors`.
inline double log_domain_prior(const Order& order, const PriorRanges& priors) {
  double log_prior = -order.q() * std::log(priors.lambda.width()) -
                     order.s() * std::log(priors.alpha.width() * priors.beta.width()) + order.s() * std::log(2.0);
  for (int j = 2; j <= order.q(); ++j) log_prior += std::log(static_cast<double>(j));
  for (int j = 2; j <= order.s(); ++j) log_prior += std::log(static_cast<double>(j));
  return log_prior;
}

namespace detail {

/// Multivariate t_ν (integer ν): log density at x and draws, location μ and scale matrix C = LLᵀ.
struct MultivariateT {
  Eigen::VectorXd mean;
  Eigen::MatrixXd chol;
  int nu = 5;
  double log_norm = 0.0;
  MultivariateT(Eigen::VectorXd m, const Eigen::MatrixXd& cov, int dof) : mean(std::move(m)), nu(dof) {
    chol = Eigen::LLT<Eigen::MatrixXd>(cov).matrixL();
    const double d = static_cast<double>(mean.size()), n = static_cast<double>(nu);
    log_norm = std::lgamma(0.5 * (n + d)) - std::lgamma(0.5 * n) - 0.5 * d * std::log(n * EIGEN_PI) -
               chol.diagonal().array().log().sum();
  }
  double log_density(const Eigen::VectorXd& x) const {
    const Eigen::VectorXd z = chol.triangularView<Eigen::Lower>().solve(x - mean);
    return log_norm - 0.5 * (nu + static_cast<double>(mean.size())) * std::log1p(z.squaredNorm() / nu);
  }
  Eigen::VectorXd draw(Rng& rng) const {
    Eigen::VectorXd z(mean.size());
    for (Eigen::Index k = 0; k < z.size(); ++k) z[k] = rng.normal();
    return mean + chol * z / std::sqrt(chi_square_draw(nu, rng) / nu);
  }
};

/// ψ in D and in the pole ranges of `priors` (pole_space.hpp packing).
inline bool in_domain(const Order& order, const PriorRanges& priors, const Eigen::VectorXd& psi) {
  const int q = order.q();
  for (int j = 0; j < q; ++j)
    if (psi[j] < priors.lambda.lo || psi[j] > priors.lambda.hi || (j > 0 && psi[j] < psi[j - 1])) return false;
  for (int s = 0; s < order.s(); ++s) {
    const double al = psi[q + 2 * s], be = psi[q + 2 * s + 1];
    if (al < priors.alpha.lo || al > priors.alpha.hi || be < 0.0 || be > priors.beta.hi) return false;
    if (s > 0 && be < psi[q + 2 * s - 1]) return false;
  }
  return true;
}

}  // namespace detail

/// ln of the mean of the ratios e^{log_ratio} (ln Z), the standard error of that mean relative to it, and
/// the Kish effective sample size.
inline ImportanceEstimate mean_of_ratios(const std::vector<double>& log_ratio) {
  double top = -std::numeric_limits<double>::infinity();
  for (double v : log_ratio) top = std::max(top, v);
  double sum = 0.0, sum2 = 0.0;
  for (double v : log_ratio) {
    const double e = std::exp(v - top);
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(log_ratio.size()), mean_ratio = sum / n;
  return {top + std::log(mean_ratio), std::sqrt((sum2 / n - mean_ratio * mean_ratio) / n) / mean_ratio, sum * sum / sum2};
}

/// ln Z of `order` under `priors` (ResiduePrior::gaussian) by importance sampling, q built from the posterior
/// samples of `runs` (θ as fit_order returns them, folded to the reduced form), `kernels` resampled points per
/// run, `draws` proposal draws.
inline ImportanceEstimate importance_log_z(const Measurement& data, const Order& order, const PriorRanges& priors,
                                           const std::vector<const ModelResult*>& runs, int kernels, long draws,
                                           std::uint64_t seed) {
  const ResidueEvidence evidence(data, order, DataCount::two_per_point, priors.admittance_scale);
  const std::vector<int> poles = pole_indices(order);
  const Eigen::Index d = static_cast<Eigen::Index>(poles.size());
  Rng rng(seed);
  // Per run: K resampled posterior points, their covariance Σ_r; kernels t_5(c, h²Σ_r) and a defensive
  // t_3(mean_r, 4Σ_r). Runs are not pooled: a run stuck in another mode would otherwise widen every kernel.
  std::vector<detail::MultivariateT> kernel, wide;
  const double dd = static_cast<double>(d), k = static_cast<double>(kernels);
  const double h = std::pow(4.0 / (dd + 2.0), 1.0 / (dd + 4.0)) * std::pow(k, -1.0 / (dd + 4.0));
  for (const ModelResult* m : runs) {
    const auto idx = resample_indices(posterior_weights(m->run), static_cast<std::size_t>(kernels), rng);
    std::vector<Eigen::VectorXd> centres;
    for (std::size_t i : idx) {
      Eigen::VectorXd psi(d);
      for (Eigen::Index j = 0; j < d; ++j) psi[j] = m->run.point(i)[poles[static_cast<std::size_t>(j)]];
      centres.push_back(psi);
    }
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
    for (const auto& c : centres) mean += c;
    mean /= k;
    Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(d, d);
    for (const auto& c : centres) cov += (c - mean) * (c - mean).transpose();
    cov /= k - 1.0;
    cov.diagonal().array() += 1e-9 * cov.diagonal().array().maxCoeff() + 1e-12;
    for (const auto& c : centres) kernel.emplace_back(c, h * h * cov, 5);
    wide.emplace_back(mean, 4.0 * cov, 3);
  }
  constexpr double kWide = 0.2;
  const double log_kernels = std::log(static_cast<double>(kernel.size())), log_wides = std::log(static_cast<double>(wide.size()));
  const auto log_q = [&](const Eigen::VectorXd& x) {
    double lk = -std::numeric_limits<double>::infinity(), lw = lk;
    for (const auto& t : kernel) lk = log_add_exp(lk, t.log_density(x));
    for (const auto& t : wide) lw = log_add_exp(lw, t.log_density(x));
    return log_add_exp(std::log1p(-kWide) + lk - log_kernels, std::log(kWide) + lw - log_wides);
  };
  const double log_prior = log_domain_prior(order, priors);
  std::vector<double> log_ratio;
  for (long i = 0; i < draws; ++i) {
    const Eigen::VectorXd psi = rng.uniform() < kWide ? wide[static_cast<std::size_t>(rng.below(wide.size()))].draw(rng)
                                                       : kernel[static_cast<std::size_t>(rng.below(kernel.size()))].draw(rng);
    if (!detail::in_domain(order, priors, psi)) {
      log_ratio.push_back(-std::numeric_limits<double>::infinity());
      continue;
    }
    log_ratio.push_back(pole_log_evidence(evidence, psi.data()) + log_prior - log_q(psi));
  }
  return mean_of_ratios(log_ratio);
}

}  // namespace admitgen::test

// SPDX-License-Identifier: MIT
#include "inference/residue_draws.hpp"

#include "inference/box_least_squares.hpp"
#include "inference/normal_interval.hpp"
#include "inference/student_t.hpp"

#include <boost/math/special_functions/gamma.hpp>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace admitgen {
namespace {

Eigen::VectorXd gibbs(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Rng& rng,
                      int sweeps) {
  const Eigen::Index p = c.mean.size();
  Eigen::VectorXd r = c.mean.cwiseMax(lo).cwiseMin(hi);
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (Eigen::Index k = 0; k < p; ++k) {
      const Eigen::VectorXd y = r - c.mean;
      const double mkk = c.m(k, k);
      const double shift = (c.m.row(k).dot(y) - mkk * y[k]) / mkk;  // Σ_{j≠k} M_kj y_j / M_kk
      const double centre = c.mean[k] - shift;
      const double q_rest = std::max(y.dot(c.m * y) - mkk * (r[k] - centre) * (r[k] - centre), 0.0);
      const double tau = std::sqrt((c.s_min + q_rest) / (mkk * (c.k - 1.0)));
      r[k] = centre + tau * truncated_student_t_draw(c.k - 1.0, (lo[k] - centre) / tau, (hi[k] - centre) / tau, rng);
      r[k] = std::clamp(r[k], lo[k], hi[k]);
    }
  return r;
}

}  // namespace

BoxMassSimulator::BoxMassSimulator(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi)
    : c_(c) {
  const Eigen::Index p = c.mean.size();
  Eigen::MatrixXd inv = Eigen::MatrixXd::Identity(p, p);
  c.chol.triangularView<Eigen::Lower>().solveInPlace(inv);  // L̃⁻¹
  const Eigen::MatrixXd cov = inv.transpose() * inv;        // M̃⁻¹
  const Eigen::VectorXd a = lo.cwiseQuotient(c.scale) - c.mean.cwiseQuotient(c.scale);
  const Eigen::VectorXd b = hi.cwiseQuotient(c.scale) - c.mean.cwiseQuotient(c.scale);
  // Most constrained first: the smallest marginal mass of the interval at the t's typical scale.
  const double sigma = std::sqrt(c.s_min / c.nu);
  std::vector<double> mass(static_cast<std::size_t>(p));
  for (Eigen::Index k = 0; k < p; ++k) {
    const double sd = sigma * std::sqrt(cov(k, k));
    mass[static_cast<std::size_t>(k)] = log_normal_interval(a[k] / sd, b[k] / sd);
  }
  order_.resize(static_cast<std::size_t>(p));
  std::iota(order_.begin(), order_.end(), Eigen::Index{0});
  std::stable_sort(order_.begin(), order_.end(), [&](Eigen::Index i, Eigen::Index j) {
    return mass[static_cast<std::size_t>(i)] < mass[static_cast<std::size_t>(j)];
  });
  Eigen::MatrixXd permuted(p, p);
  a_.resize(p);
  b_.resize(p);
  for (Eigen::Index i = 0; i < p; ++i) {
    const Eigen::Index k = order_[static_cast<std::size_t>(i)];
    a_[i] = a[k];
    b_[i] = b[k];
    for (Eigen::Index j = 0; j < p; ++j) permuted(i, j) = cov(k, order_[static_cast<std::size_t>(j)]);
  }
  chol_ = Eigen::LLT<Eigen::MatrixXd>(permuted).matrixL();
  u_.resize(p);
  uniforms_.resize(p);
  // The tilt (docs/method.md, "Tilting the box-mass replicate"): given W the mode of the truncated normal
  // in u (y − ŷ = C u σ) is μ = v*/σ, v* = C⁻¹(y* − ŷ), y* the box-constrained minimiser of
  // (y − ŷ)ᵀM̃(y − ŷ). Zero (plain GHK, bit for bit) when r̂ lies in the box.
  tilt_ = Eigen::VectorXd::Zero(p);
  if (!in_residue_box(c.mean, lo, hi)) {
    const Eigen::VectorXd mean_scaled = c.mean.cwiseQuotient(c.scale);
    const Eigen::VectorXd y_star = scaled_box_minimiser(c, lo, hi);
    for (Eigen::Index i = 0; i < p; ++i) {
      const Eigen::Index k = order_[static_cast<std::size_t>(i)];
      tilt_[i] = y_star[k] - mean_scaled[k];
    }
    chol_.triangularView<Eigen::Lower>().solveInPlace(tilt_);
  }
}

double BoxMassSimulator::draw(Rng& rng) {
  const double w = chi_square_draw(c_.nu, rng);
  for (Eigen::Index i = 0; i < uniforms_.size(); ++i) uniforms_[i] = rng.uniform();
  return std::exp(log_replicate(w, uniforms_.data(), nullptr));
}

double BoxMassSimulator::log_replicate(double w, const double* uniforms, Eigen::VectorXd* deviation) {
  const double root_w = std::sqrt(w / c_.s_min);  // 1/σ, σ = √(S_min/W)
  double log_estimate = 0.0;
  for (Eigen::Index i = 0; i < u_.size(); ++i) {
    const double partial = chol_.row(i).head(i).dot(u_.head(i)), diag = chol_(i, i);
    const double l = (a_[i] * root_w - partial) / diag, h = (b_[i] * root_w - partial) / diag;
    // u_i ~ N(μ_i, 1) on [l, h], weight P_i(μ_i) φ(u_i)/φ(u_i − μ_i) = P_i(μ_i) exp(μ_i²/2 − u_i μ_i).
    const double mu = tilt_[i] * root_w;
    double z = 0.0;
    log_estimate += normal_interval_draw(l - mu, h - mu, uniforms[i], z);
    u_[i] = z + mu;
    log_estimate += mu * (0.5 * mu - u_[i]);
  }
  if (deviation) {  // r − r̂ = D (y − ŷ), y − ŷ = C u/root_w in the simulator's order
    const Eigen::VectorXd y = chol_.triangularView<Eigen::Lower>() * u_ / root_w;
    deviation->resize(u_.size());
    for (Eigen::Index i = 0; i < u_.size(); ++i) {
      const Eigen::Index k = order_[static_cast<std::size_t>(i)];
      (*deviation)[k] = c_.scale[k] * y[i];
    }
  }
  return log_estimate;
}

BoxMassEstimate estimate_box_mass(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                  long m, Rng& rng) {
  BoxMassSimulator simulator(c, lo, hi);
  double sum = 0.0, sum2 = 0.0;
  for (long d = 0; d < m; ++d) {
    const double x = simulator.draw(rng);
    sum += x;
    sum2 += x * x;
  }
  const double md = static_cast<double>(m), mean = sum / md;
  return {mean, std::max(sum2 - sum * mean, 0.0) / (md - 1.0)};
}

double chi_square_quantile(double nu, double u) { return 2.0 * boost::math::gamma_p_inv(0.5 * nu, u); }

bool in_residue_box(const Eigen::VectorXd& r, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  return (r.array() >= lo.array()).all() && (r.array() <= hi.array()).all();
}

Eigen::VectorXd scaled_box_minimiser(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  const Eigen::MatrixXd m_scaled = c.chol * c.chol.transpose();  // M̃
  return box_least_squares(m_scaled, c.mean.cwiseQuotient(c.scale), lo.cwiseQuotient(c.scale),
                           hi.cwiseQuotient(c.scale));
}

Eigen::VectorXd untruncated_residue_draw(const ResidueConditional& c, Rng& rng) {
  Eigen::VectorXd z(c.mean.size());
  for (Eigen::Index k = 0; k < z.size(); ++k) z[k] = rng.normal();
  const double w = chi_square_draw(c.nu, rng);
  z = c.chol.transpose().triangularView<Eigen::Upper>().solve(z);  // L̃⁻ᵀ z
  return c.mean + std::sqrt(c.s_min / w) * c.scale.cwiseProduct(z);
}

Eigen::VectorXd draw_residues(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                              Rng& rng, ResidueDrawMethod& method, int tries, int sweeps) {
  for (int t = 0; t < tries; ++t) {
    Eigen::VectorXd r = untruncated_residue_draw(c, rng);
    if (in_residue_box(r, lo, hi)) {
      method = ResidueDrawMethod::rejection;
      return r;
    }
  }
  method = ResidueDrawMethod::gibbs;
  return gibbs(c, lo, hi, rng, sweeps);
}

}  // namespace admitgen

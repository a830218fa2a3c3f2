// SPDX-License-Identifier: MIT
#include "inference/residue_marginal.hpp"

#include "core/errors.hpp"
#include "inference/pole_space.hpp"
#include "inference/student_t.hpp"
#include "model/residue_basis.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {

ResidueMarginal::ResidueMarginal(const Measurement& data, const Order& order, DataCount count,
                                 const PriorRanges& ranges)
    : order_(order),
      omega_(data.omega()),
      omega2_(omega_.square()),
      k_(real_data_count(count, data.size())),
      p_(residue_count(order)),
      tail_(k_ - p_) {
  ADMITGEN_ENSURE(k_ > p_, "K = {} real data for {} residues", k_, p_);
  const Eigen::Index n = omega_.size();
  b_.resize(2 * n);
  b_.head(n) = data.y.real().matrix();
  b_.tail(n) = data.y.imag().matrix();
  b_norm2_ = b_.squaredNorm();
  const double nu = k_ - p_;
  constant_ = MarginalGaussian::log_constant(nu) - log_residue_box_volume(order, ranges);
  residue_box(order, ranges, lo_, hi_);
  a_.resize(2 * n, p_);
  g_.resize(p_);
  c_.k = k_;
  c_.nu = nu;
}

void ResidueMarginal::fill_basis(const double* poles, Eigen::MatrixXd& a) const {
  // Columns of model/residue_basis.hpp, each as whole-array arithmetic on ω (d = λ² + ω²,
  // d± = α² + (ω ± β)²):
  //   1/(λ + jω) = (λ − jω)/d
  //   φ_B = 1/(α + j(ω+β)) + 1/(α + j(ω−β)) = α/d+ + α/d− − j[(ω+β)/d+ + (ω−β)/d−]
  //   φ_C = j/(α + j(ω+β)) − j/(α + j(ω−β)) = (ω+β)/d+ − (ω−β)/d− + jα(1/d+ − 1/d−)
  const Eigen::Index n = omega_.size();
  a.resize(2 * n, p_);
  a.col(0).head(n).setOnes();
  a.col(0).tail(n).setZero();
  Eigen::Index k = 1;
  for (int q = 0; q < order_.q(); ++q, ++k) {
    const double lam = poles[q];
    inv_ = (lam * lam + omega2_).inverse();
    a.col(k).head(n) = (lam * inv_).matrix();
    a.col(k).tail(n) = (-omega_ * inv_).matrix();
  }
  for (int s = 0; s < order_.s(); ++s, k += 2) {
    const double al = poles[order_.q() + 2 * s], be = poles[order_.q() + 2 * s + 1];
    // One division per pair (as model/multipole.hpp): 1/d+ = d−/(d+ d−), 1/d− = d+/(d+ d−).
    const Eigen::ArrayXd d_plus = al * al + (omega_ + be).square(), d_minus = al * al + (omega_ - be).square();
    inv_ = (d_plus * d_minus).inverse();
    dp_ = d_minus * inv_;  // 1/d+
    dm_ = d_plus * inv_;   // 1/d−
    a.col(k).head(n) = (al * (dp_ + dm_)).matrix();
    a.col(k).tail(n) = (-((omega_ + be) * dp_ + (omega_ - be) * dm_)).matrix();
    a.col(k + 1).head(n) = ((omega_ + be) * dp_ - (omega_ - be) * dm_).matrix();
    a.col(k + 1).tail(n) = (al * (dp_ - dm_)).matrix();
  }
}

const ResidueConditional& ResidueMarginal::conditional(const double* poles) const {
  fill_basis(poles, a_);
  ResidueConditional& c = c_;
  c.valid = false;
  c.log_marginal = -std::numeric_limits<double>::infinity();
  // M = AᵀA and g = Aᵀb by column dot products (p ≤ ~10 columns: cheaper than a blocked product).
  c.m.resize(p_, p_);
  for (Eigen::Index j = 0; j < p_; ++j) {
    g_[j] = a_.col(j).dot(b_);
    for (Eigen::Index k = 0; k <= j; ++k) c.m(j, k) = c.m(k, j) = a_.col(j).dot(a_.col(k));
  }
  const Eigen::VectorXd& g = g_;
  // Jacobi scaling: the columns differ by orders of magnitude (1 for G∞, ~1/λ for the poles).
  c.scale = c.m.diagonal().cwiseSqrt().cwiseInverse();
  if (!c.scale.allFinite()) return c;
  scaled_ = c.scale.asDiagonal() * c.m * c.scale.asDiagonal();
  llt_.compute(scaled_);
  if (llt_.info() != Eigen::Success) return c;
  const auto& llt = llt_;
  c.chol = llt.matrixL();
  if (!(c.chol.diagonal().array() > 0.0).all()) return c;
  c.mean = c.scale.asDiagonal() * llt.solve(c.scale.asDiagonal() * g);
  // S(r̂) = |b|² − 2gᵀr̂ + r̂ᵀMr̂ is second-order in the error of r̂ (the form |b|² − gᵀr̂ is first-order).
  c.s_min = b_norm2_ - 2.0 * g.dot(c.mean) + c.mean.dot(c.m * c.mean);
  if (!(c.s_min > 1e-12 * b_norm2_)) c.s_min = (b_ - a_ * c.mean).squaredNorm();  // cancellation: recompute
  c.s_min = std::max(c.s_min, 1e-300);
  const double log_det_m = 2.0 * (c.chol.diagonal().array().log().sum() - c.scale.array().log().sum());

  // Coordinate marginals: t_ν with scale s_k = √(S_min/ν · (M⁻¹)_kk), (M⁻¹)_kk = D_k² Σ_i (L̃⁻¹)_ik².
  inv_chol_ = llt.matrixL().solve(Eigen::MatrixXd::Identity(p_, p_));
  const auto tail = [&](double z) { return tail_.upper(z); };
  // P(−z_lo ≤ T ≤ z_hi) and its complement, from upper tails only (no cancellation against 1 when the
  // centre lies outside the interval).
  const auto interval = [&](double z_lo, double z_hi, double& inside, double& outside) {
    if (z_lo < 0.0) {
      inside = tail(-z_lo) - tail(z_hi);
      outside = 1.0 - inside;
    } else if (z_hi < 0.0) {
      inside = tail(-z_hi) - tail(z_lo);
      outside = 1.0 - inside;
    } else {
      outside = tail(z_lo) + tail(z_hi);
      inside = 1.0 - outside;
    }
  };
  double sum_outside = 0.0, min_inside = 1.0;
  for (Eigen::Index k = 0; k < p_; ++k) {
    const double s = c.scale[k] * inv_chol_.col(k).norm() * std::sqrt(c.s_min / c.nu);
    double inside, outside;
    interval((c.mean[k] - lo_[k]) / s, (hi_[k] - c.mean[k]) / s, inside, outside);
    sum_outside += outside;
    min_inside = std::min(min_inside, inside);
  }
  // One more upper bound, along the direction v in which the t is widest relative to the box (power
  // iteration on W⁻¹M⁻¹W⁻¹, W = diag(box widths)): P_box ≤ P(vᵀr ∈ vᵀ·box), where vᵀ·box is the interval
  // [Σ min(v_k lo_k, v_k hi_k), Σ max(…)] and vᵀr is a univariate t of scale √(S_min/ν · vᵀM⁻¹v). Any v
  // gives a valid bound; this one is tight where residues are nearly degenerate (coinciding poles).
  if (p_ > 1) {
    const Eigen::VectorXd width = hi_ - lo_;
    const auto m_inv = [&](const Eigen::VectorXd& x) {  // M⁻¹x = D L̃⁻ᵀ L̃⁻¹ D x
      return Eigen::VectorXd(c.scale.cwiseProduct(inv_chol_.transpose() * (inv_chol_ * c.scale.cwiseProduct(x))));
    };
    Eigen::VectorXd u = Eigen::VectorXd::Ones(p_);
    for (int it = 0; it < 8; ++it) {
      u = m_inv(u.cwiseQuotient(width)).cwiseQuotient(width);  // W⁻¹M⁻¹W⁻¹u: covariance in box units
      u /= u.norm();
    }
    // u is the direction in box units x = W⁻¹(r − lo); the functional uᵀx is vᵀr + const with v = W⁻¹u.
    const Eigen::VectorXd v = u.cwiseQuotient(width);
    const double var = v.dot(m_inv(v)) * c.s_min / c.nu;
    double lo_v = 0.0, hi_v = 0.0;
    for (Eigen::Index k = 0; k < p_; ++k) {
      lo_v += std::min(v[k] * lo_[k], v[k] * hi_[k]);
      hi_v += std::max(v[k] * lo_[k], v[k] * hi_[k]);
    }
    if (var > 0.0 && std::isfinite(var)) {
      const double s = std::sqrt(var), centre = v.dot(c.mean);
      double inside, outside;
      interval((centre - lo_v) / s, (hi_v - centre) / s, inside, outside);
      min_inside = std::min(min_inside, inside);
    }
  }
  // P_up is floored at 1e-300 (keeps ln L finite where the t lies far outside the box); a floor only
  // raises the upper bound, and such points have P_lo = 0, so they count fully in the truncation check.
  c.log_p_up = std::log(std::max(min_inside, 1e-300));
  c.log_p_lo = sum_outside < 1.0 ? std::log1p(-sum_outside) : -std::numeric_limits<double>::infinity();
  c.log_marginal = constant_ - 0.5 * c.nu * std::log(c.s_min) - 0.5 * log_det_m + c.log_p_up;
  c.valid = std::isfinite(c.log_marginal);
  return c;
}

double ResidueMarginal::operator()(const double* poles) const { return conditional(poles).log_marginal; }

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "inference/residue_marginal.hpp"

#include "core/errors.hpp"
#include "inference/box_least_squares.hpp"
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
      points_(omega_, data.y),
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
  gram_work_.resize(residue_gram_work_size(p_));
  width_ = hi_ - lo_;
  slab_lo_.resize(p_);
  slab_hi_.resize(p_);
  // Nodes of y = ln(W/ν), W ~ χ²_ν: density ∝ exp(ν/2 · (y − e^y)), sd ≈ √(2/ν); 33 trapezoid nodes over
  // ±10 sd of the mode y = 0 (exponentially accurate for this smooth, fast-decaying integrand).
  constexpr int kNodes = 33;
  const double sd = std::sqrt(2.0 / nu);
  double sum = 0.0;
  for (int i = 0; i < kNodes; ++i) {
    const double y = sd * (-10.0 + 20.0 * i / (kNodes - 1));
    mixture_y_.push_back(y);
    mixture_w_.push_back(std::exp(0.5 * nu * (y - std::expm1(y) - 1.0) + 0.5 * nu));
    sum += mixture_w_.back();
  }
  for (double& w : mixture_w_) w /= sum;
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
  ResidueConditional& c = c_;
  c.valid = false;
  c.log_marginal = -std::numeric_limits<double>::infinity();
  // M = AᵀA and g = Aᵀb in one fused pass over the points (inference/residue_gram.hpp).
  c.m.resize(p_, p_);
  residue_gram(points_, order_.q(), order_.s(), poles, gram_work_.data(), c.m.data(), g_.data());
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
  mean_scaled_ = c.scale.cwiseProduct(g);
  llt.solveInPlace(mean_scaled_);
  c.mean = c.scale.cwiseProduct(mean_scaled_);
  // S(r̂) = |b|² − 2gᵀr̂ + r̂ᵀMr̂ is second-order in the error of r̂ (the form |b|² − gᵀr̂ is first-order).
  v_.noalias() = c.m * c.mean;
  c.s_min = b_norm2_ - 2.0 * g.dot(c.mean) + c.mean.dot(v_);
  if (!(c.s_min > 1e-12 * b_norm2_)) {  // cancellation: recompute from the stored basis
    fill_basis(poles, a_);
    c.s_min = (b_ - a_ * c.mean).squaredNorm();
  }
  c.s_min = std::max(c.s_min, 1e-300);
  const double log_det_m = 2.0 * (c.chol.diagonal().array().log().sum() - c.scale.array().log().sum());

  // Coordinate marginals: t_ν with scale s_k = √(S_min/ν · (M⁻¹)_kk), (M⁻¹)_kk = D_k² Σ_i (L̃⁻¹)_ik².
  inv_chol_.setIdentity(p_, p_);
  llt.matrixL().solveInPlace(inv_chol_);
  const auto tail = [&](double z) { return tail_.upper(z); };
  // P(−z_lo ≤ T ≤ z_hi), its complement and ln of an upper bound of it, from upper tails only (no
  // cancellation against 1 when the centre lies outside the interval). Where the interval lies beyond
  // the resolvable tail (inside = 0 in double), the bound stays finite (StudentTail::log_upper_bound): the
  // sampled likelihood then still falls with the distance of r̂ from the box instead of meeting a floor.
  const auto interval = [&](double z_lo, double z_hi, double& inside, double& outside, double& log_inside) {
    if (z_lo < 0.0) {
      inside = tail(-z_lo) - tail(z_hi);
      outside = 1.0 - inside;
      log_inside = inside > 0.0 ? std::log(inside) : tail_.log_upper_bound(-z_lo);
    } else if (z_hi < 0.0) {
      inside = tail(-z_hi) - tail(z_lo);
      outside = 1.0 - inside;
      log_inside = inside > 0.0 ? std::log(inside) : tail_.log_upper_bound(-z_hi);
    } else {
      outside = tail(z_lo) + tail(z_hi);
      inside = 1.0 - outside;
      log_inside = std::log(std::max(inside, 1e-300));
    }
  };
  double sum_outside = 0.0, log_min_inside = 0.0;
  for (Eigen::Index k = 0; k < p_; ++k) {
    const double s = c.scale[k] * inv_chol_.col(k).norm() * std::sqrt(c.s_min / c.nu);
    double inside, outside, log_inside;
    interval((c.mean[k] - lo_[k]) / s, (hi_[k] - c.mean[k]) / s, inside, outside, log_inside);
    sum_outside += outside;
    log_min_inside = std::min(log_min_inside, log_inside);
  }
  // Directions v_j = W⁻¹e_j, e_j the eigenvectors of W⁻¹M⁻¹W⁻¹ (the covariance in box units, W =
  // diag(box widths)), are M⁻¹-orthogonal, so the projections v_jᵀr are uncorrelated univariate t's of scale
  // √(S_min/ν · e_jᵀW⁻¹M⁻¹W⁻¹e_j) (docs/method.md, "Truncation by the residue box"). Each interval
  // probability P(v_jᵀr ∈ v_jᵀ·box), vᵀ·box = [Σ min(v_k lo_k, v_k hi_k), Σ max(…)], is an upper bound of
  // P_box; their product P_× accounts for every degenerate direction at once (two or more coinciding
  // poles) and is what the sampler uses, clamped to [P_lo, P_up].
  // The supporting half-space at the box-constrained minimiser y* of S (docs/method.md, "The box mass the
  // sampler uses"): in Jacobi-scaled coordinates y = D⁻¹r, with d = M̃(y* − ŷ), the box lies in
  // {dᵀ(y − ŷ) ≥ c_h}, c_h = Σ_k min(d_k a_k, d_k b_k) − dᵀŷ (a, b the scaled box), and dᵀ(y − ŷ) is a univariate
  // t of scale √(S_min/ν · dᵀM̃⁻¹d) = √(S_min/ν · (y* − ŷ)ᵀd). Valid for any y* in the box; at the true
  // minimiser c_h = (y* − ŷ)ᵀd = S(r*) − S_min and the bound P(T ≥ √(ν(S(r*) − S_min)/S_min)) accounts for
  // every violated face at once.
  if (sum_outside > 0.0) {
    m_scaled_ = scaled_;  // M̃ (scaled_ is reused below)
    box_a_ = lo_.cwiseQuotient(c.scale);
    box_b_ = hi_.cwiseQuotient(c.scale);
    const Eigen::VectorXd y_star = box_least_squares(m_scaled_, mean_scaled_, box_a_, box_b_);
    const Eigen::VectorXd delta = y_star - mean_scaled_;
    const Eigen::VectorXd d = m_scaled_ * delta;
    const double q = delta.dot(d);
    if (q > 0.0) {
      double c_h = -d.dot(mean_scaled_);
      for (Eigen::Index k = 0; k < p_; ++k) c_h += std::min(d[k] * box_a_[k], d[k] * box_b_[k]);
      const double z = c_h / std::sqrt(c.s_min * q / c.nu);
      if (z > 0.0) {
        const double inside = tail(z);
        log_min_inside = std::min(log_min_inside, inside > 0.0 ? std::log(inside) : tail_.log_upper_bound(z));
      }
    }
  }
  int cut = 0;  // directions whose slab holds less than 1 − 1e-12 of the t
  double log_product = 0.0;
  // When no coordinate marginal reaches a face (every tail beyond the negligible quantile is exactly 0),
  // P_lo = P_up = 1 and the clamp below gives P̃ = 1 whatever the slabs say: no eigendecomposition.
  if (p_ > 1 && sum_outside > 0.0) {
    const Eigen::ArrayXd& width = width_;
    box_cov_.noalias() = inv_chol_ * (c.scale.array() / width).matrix().asDiagonal();  // L̃⁻¹ D W⁻¹
    scaled_.noalias() = box_cov_.transpose() * box_cov_;
    eigen_.compute(scaled_);
    for (Eigen::Index j = 0; j < p_; ++j) {
      const double var = eigen_.eigenvalues()[j] * c.s_min / c.nu;
      slab_lo_[j] = -std::numeric_limits<double>::infinity();
      slab_hi_[j] = std::numeric_limits<double>::infinity();
      if (!(var > 0.0) || !std::isfinite(var)) continue;
      v_ = eigen_.eigenvectors().col(j).cwiseQuotient(width.matrix());
      const Eigen::VectorXd& v = v_;
      double lo_v = 0.0, hi_v = 0.0;
      for (Eigen::Index k = 0; k < p_; ++k) {
        lo_v += std::min(v[k] * lo_[k], v[k] * hi_[k]);
        hi_v += std::max(v[k] * lo_[k], v[k] * hi_[k]);
      }
      const double s = std::sqrt(var), centre = v.dot(c.mean);
      slab_lo_[j] = (lo_v - centre) / s;
      slab_hi_[j] = (hi_v - centre) / s;
      double inside, outside, log_inside;
      interval(-slab_lo_[j], slab_hi_[j], inside, outside, log_inside);
      log_min_inside = std::min(log_min_inside, log_inside);
      log_product += outside < 0.5 ? std::log1p(-outside) : std::log(std::max(inside, 1e-300));
      if (outside > 1e-12) ++cut;
    }
  }
  c.log_p_up = log_min_inside;
  c.log_p_lo = sum_outside < 1.0 ? std::log1p(-sum_outside) : -std::numeric_limits<double>::infinity();
  // P̃: with one cut direction the product is that slab's exact t probability; with several the slabs
  // share the t's scale variable W ~ χ²_ν, so P̃ = E_W[Π_j P_j | W] (Gaussian slabs given W; quadrature in
  // ln W). Where P_up < 1e-6 (residues far outside the box: no posterior weight) P̃ = P_up.
  c.log_p_sampled = c.log_p_up;
  if (c.log_p_up > std::log(1e-6)) {
    c.log_p_sampled = cut <= 1 ? log_product : log_slab_mixture();
    c.log_p_sampled = std::clamp(c.log_p_sampled, c.log_p_lo, c.log_p_up);
  }
  c.log_marginal = constant_ - 0.5 * c.nu * std::log(c.s_min) - 0.5 * log_det_m + c.log_p_sampled;
  c.valid = std::isfinite(c.log_marginal);
  return c;
}

double ResidueMarginal::log_slab_mixture() const {
  // Given W the slab coordinates are independent normals N(0, ν/W); trapezoid nodes on y = ln(W/ν)
  // (weights ∝ the χ²_ν density of W times W, normalised to sum 1).
  double total = 0.0;
  for (std::size_t i = 0; i < mixture_y_.size(); ++i) {
    const double root = std::exp(0.5 * mixture_y_[i]);  // √(W/ν)
    double prob = mixture_w_[i];
    for (Eigen::Index j = 0; j < p_ && prob > 0.0; ++j) {
      const double a = slab_lo_[j] * root, b = slab_hi_[j] * root;
      prob *= a > 0.0 ? 0.5 * (std::erfc(a / std::sqrt(2.0)) - std::erfc(b / std::sqrt(2.0)))
              : b < 0.0 ? 0.5 * (std::erfc(-b / std::sqrt(2.0)) - std::erfc(-a / std::sqrt(2.0)))
                        : 1.0 - 0.5 * (std::erfc(-a / std::sqrt(2.0)) + std::erfc(b / std::sqrt(2.0)));
    }
    total += prob;
  }
  return std::log(std::max(total, 1e-300));
}

double ResidueMarginal::operator()(const double* poles) const { return conditional(poles).log_marginal; }

}  // namespace admitgen

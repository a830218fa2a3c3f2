// SPDX-License-Identifier: MIT
#include "inference/residue_marginal.hpp"

#include "core/errors.hpp"
#include "inference/box_least_squares.hpp"
#include "inference/normal_interval.hpp"
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
  // ln of the normalisation of the density of y = ln(W/ν), W ~ χ²_ν (log_slab_mixture).
  mixture_log_norm_ = 0.5 * nu * std::log(0.5 * nu) - std::lgamma(0.5 * nu);
  mixture_terms_.resize(33);
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

bool ResidueMarginal::solve(const double* poles) const {
  ResidueConditional& c = c_;
  c.valid = false;
  c.log_marginal = -std::numeric_limits<double>::infinity();
  c.log_p_up = c.log_p_lo = c.log_p_sampled = 0.0;
  // M = AᵀA and g = Aᵀb in one fused pass over the points (inference/residue_gram.hpp).
  c.m.resize(p_, p_);
  residue_gram(points_, order_.q(), order_.s(), poles, gram_work_.data(), c.m.data(), g_.data());
  const Eigen::VectorXd& g = g_;
  // Jacobi scaling: the columns differ by orders of magnitude (1 for G∞, ~1/λ for the poles).
  c.scale = c.m.diagonal().cwiseSqrt().cwiseInverse();
  if (!c.scale.allFinite()) return false;
  scaled_ = c.scale.asDiagonal() * c.m * c.scale.asDiagonal();
  llt_.compute(scaled_);
  bool normal_equations = llt_.info() == Eigen::Success;
  if (normal_equations) {
    c.chol = llt_.matrixL();
    normal_equations = (c.chol.diagonal().array() > 0.0).all();
  }
  if (normal_equations) {
    mean_scaled_ = c.scale.cwiseProduct(g);
    llt_.solveInPlace(mean_scaled_);
    // S(r̂) = |b|² − 2gᵀr̂ + r̂ᵀMr̂ is second-order in the error of r̂ (the form |b|² − gᵀr̂ is first-order),
    // but it subtracts terms of size |ŷ|₁² (ŷ = D⁻¹r̂: each term's share of the fit in the data's norm) from
    // |b|²: where the terms cancel each other (near-coincident poles with large opposite residues) its
    // rounding error exceeds S_min itself (docs/method.md, "Accuracy of the normal equations").
    normal_equations = mean_scaled_.lpNorm<1>() <= kNormalEquationsGrowth * std::sqrt(b_norm2_);
  }
  if (normal_equations) {
    c.mean = c.scale.cwiseProduct(mean_scaled_);
    v_.noalias() = c.m * c.mean;
    c.s_min = b_norm2_ - 2.0 * g.dot(c.mean) + c.mean.dot(v_);
    if (!(c.s_min > 1e-12 * b_norm2_)) {  // cancellation: recompute from the stored basis
      fill_basis(poles, a_);
      c.s_min = (b_ - a_ * c.mean).squaredNorm();
    }
  } else if (!solve_by_qr(poles)) {
    return false;
  }
  c.s_min = std::max(c.s_min, 1e-300);
  const double log_det_m = 2.0 * (c.chol.diagonal().array().log().sum() - c.scale.array().log().sum());
  c.log_untruncated = constant_ - 0.5 * c.nu * std::log(c.s_min) - 0.5 * log_det_m;
  return std::isfinite(c.log_untruncated);
}

bool ResidueMarginal::solve_by_qr(const double* poles) const {
  // Householder QR of the Jacobi-scaled basis A D = Q R: ŷ = R⁻¹Qᵀb, M̃ = RᵀR (L̃ = Rᵀ with the signs of
  // R's diagonal made positive) and S_min = |b − A r̂|² from the explicit residual. Backward stability
  // makes |A δr̂| of order ε(|b| + |ŷ|₁), so S_min is off by at most e_S = 2√S e + e², e = γ(|b| + |ŷ|₁)
  // with γ = 4pε√(2N); where e_S exceeds 2 kSminLogTolerance/ν · S_min (ln L off by more than 0.01 nats) the
  // poles are too close to coincident for double precision and ψ is left out (ln L = −∞; docs/method.md,
  // "Accuracy of the normal equations", bounds what that leaves out).
  ResidueConditional& c = c_;
  fill_basis(poles, a_);
  a_ = a_ * c.scale.asDiagonal();
  qr_.compute(a_);
  const auto r = qr_.matrixQR().topRows(p_).triangularView<Eigen::Upper>();
  mean_scaled_ = (qr_.householderQ().transpose() * b_).head(p_);
  r.solveInPlace(mean_scaled_);
  c.chol = qr_.matrixQR().topRows(p_).transpose().triangularView<Eigen::Lower>();
  for (Eigen::Index k = 0; k < p_; ++k)
    if (c.chol(k, k) < 0.0) c.chol.col(k) = -c.chol.col(k);
  if (!(c.chol.diagonal().array() > 0.0).all()) return false;
  // M̃ and M as the factor has them (the Gram pass's copies carry the rounding this path avoids).
  scaled_.noalias() = c.chol * c.chol.transpose();
  c.m = c.scale.cwiseInverse().asDiagonal() * scaled_ * c.scale.cwiseInverse().asDiagonal();
  c.mean = c.scale.cwiseProduct(mean_scaled_);
  c.s_min = (b_ - a_ * mean_scaled_).squaredNorm();
  const double gamma = 4.0 * p_ * std::numeric_limits<double>::epsilon() * std::sqrt(static_cast<double>(a_.rows()));
  const double e = gamma * (std::sqrt(b_norm2_) + mean_scaled_.lpNorm<1>());
  return 2.0 * std::sqrt(c.s_min) * e + e * e <= 2.0 * kSminLogTolerance / c.nu * c.s_min;
}

const ResidueConditional& ResidueMarginal::untruncated(const double* poles) const {
  ResidueConditional& c = c_;
  c.valid = solve(poles);
  if (c.valid) c.log_marginal = c.log_untruncated;
  return c;
}

const ResidueConditional& ResidueMarginal::conditional(const double* poles) const {
  ResidueConditional& c = c_;
  if (!solve(poles)) return c;
  const auto llt = c.chol.triangularView<Eigen::Lower>();

  // Coordinate marginals: t_ν with scale s_k = √(S_min/ν · (M⁻¹)_kk), (M⁻¹)_kk = D_k² Σ_i (L̃⁻¹)_ik².
  inv_chol_.setIdentity(p_, p_);
  llt.solveInPlace(inv_chol_);
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
  // Upper bounds of P_box from slabs (docs/method.md, "The box mass the sampler uses"). In box units t =
  // W⁻¹(r − r̂) (W = diag(box widths)) the covariance is B = W⁻¹M⁻¹W⁻¹ · S_min/ν; for any direction u the
  // projection uᵀt is a univariate t of scale √(uᵀBu · S_min/ν) and P(uᵀt ∈ uᵀ·box) ≥ P_box (vᵀ·box =
  // [Σ min(v_k lo_k, v_k hi_k), Σ max(…)], v = W⁻¹u in r). Directions that are B-orthogonal give projections
  // that are independent given the t's scale variable, so the product of their slab probabilities, averaged
  // over that variable, is an upper bound P_× that accounts for every direction at once.
  //  - r̂ inside the box: the eigenvectors of B (the directions in which the t is widest relative to the box
  //    come first; they are tight where residues are nearly degenerate).
  //  - r̂ outside: first u₁ = W D⁻¹ d with d = M̃(y* − ŷ), y* the box-constrained minimiser of S in Jacobi-scaled
  //    coordinates y = D⁻¹r (inference/box_least_squares.hpp). Its slab starts at the supporting half-space
  //    of the box at y*, c_h = min over the box of dᵀ(y − ŷ) = (y* − ŷ)ᵀd = S(r*) − S_min at the true minimiser:
  //    this accounts for every violated face at once, P ≤ P(T ≥ √(ν(S(r*) − S_min)/S_min)). The others are the
  //    eigenvectors of ΠBΠ, Π the projector orthogonal to Bu₁.
  //    Any y* in the box gives valid bounds; only their tightness needs the exact minimiser.
  // The directions are built whitened, as z = X u with X = L̃⁻¹ D W⁻¹ (B = XᵀX, so uᵢᵀB uⱼ = zᵢᵀzⱼ): the z are
  // made orthonormal by Gram-Schmidt, which makes the u B-orthogonal to rounding whatever the spread of B's
  // eigenvalues. (Eigenvectors of B taken as they are are B-orthogonal only to ‖B‖ε; where B also has
  // eigenvalues near ‖B‖ε, well-determined residue combinations, the slabs are then correlated and their
  // product can fall below P_box.) Back in r: vⱼ = W⁻¹uⱼ = D⁻¹L̃zⱼ, of t scale √(S_min/ν) since ‖zⱼ‖ = 1.
  cut_slabs_.clear();  // directions whose slab holds less than 1 − 1e-12 of the t
  double log_product = 0.0;
  // When no coordinate marginal reaches a face (every tail beyond the negligible quantile is exactly 0),
  // P_lo = P_up = 1 and the clamp below gives P̃ = 1 whatever the slabs say: no eigendecomposition.
  int slabs = 0;
  if (sum_outside > 0.0) {
    const Eigen::ArrayXd& width = width_;
    box_cov_.noalias() = inv_chol_ * (c.scale.array() / width).matrix().asDiagonal();  // X = L̃⁻¹ D W⁻¹
    const Eigen::MatrixXd x_xt = box_cov_ * box_cov_.transpose();                      // XXᵀ: B in z
    directions_.resize(p_, p_);  // the orthonormal z, then the v in r
    m_scaled_ = scaled_;         // M̃
    box_a_ = lo_.cwiseQuotient(c.scale);
    box_b_ = hi_.cwiseQuotient(c.scale);
    const Eigen::VectorXd y_star = box_least_squares(m_scaled_, mean_scaled_, box_a_, box_b_);
    const Eigen::VectorXd d = m_scaled_ * (y_star - mean_scaled_);
    int first = 0;
    Eigen::Index dropped = -1;  // the candidate along z₁, which z₁ replaces
    if (d.squaredNorm() > 0.0 && (y_star - mean_scaled_).dot(d) > 0.0) {
      // z₁ = X u₁ = L̃⁻¹ d = L̃ᵀ(y* − ŷ)
      directions_.col(0) = (c.chol.transpose().triangularView<Eigen::Upper>() * (y_star - mean_scaled_)).normalized();
      first = 1;
      const Eigen::VectorXd w = directions_.col(0);
      const Eigen::MatrixXd proj = Eigen::MatrixXd::Identity(p_, p_) - w * w.transpose();
      eigen_.compute(proj * x_xt * proj);
      (eigen_.eigenvectors().transpose() * w).cwiseAbs().maxCoeff(&dropped);
    } else if (p_ > 1) {
      eigen_.compute(x_xt);
    }
    if (first == 1 || p_ > 1) {
      slabs = static_cast<int>(p_);
      for (Eigen::Index j = 0, k = first; j < p_ && k < p_; ++j) {
        if (j == dropped) continue;
        Eigen::VectorXd z = eigen_.eigenvectors().col(j);
        for (int pass = 0; pass < 2; ++pass)  // Gram-Schmidt twice: orthogonal to working precision
          for (Eigen::Index i = 0; i < k; ++i) z -= directions_.col(i).dot(z) * directions_.col(i);
        directions_.col(k++) = z.normalized();
      }
      for (Eigen::Index j = 0; j < slabs; ++j)
        directions_.col(j) = (llt * directions_.col(j)).cwiseQuotient(c.scale);  // v = D⁻¹L̃z
    }
    const double s = std::sqrt(c.s_min / c.nu);
    for (Eigen::Index j = 0; j < slabs; ++j) {
      const auto v = directions_.col(j);
      slab_lo_[j] = -std::numeric_limits<double>::infinity();
      slab_hi_[j] = std::numeric_limits<double>::infinity();
      if (!v.allFinite()) continue;
      double lo_v = 0.0, hi_v = 0.0;
      for (Eigen::Index k = 0; k < p_; ++k) {
        lo_v += std::min(v[k] * lo_[k], v[k] * hi_[k]);
        hi_v += std::max(v[k] * lo_[k], v[k] * hi_[k]);
      }
      const double centre = v.dot(c.mean);
      slab_lo_[j] = (lo_v - centre) / s;
      slab_hi_[j] = (hi_v - centre) / s;
      double inside, outside, log_inside;
      interval(-slab_lo_[j], slab_hi_[j], inside, outside, log_inside);
      log_min_inside = std::min(log_min_inside, log_inside);
      log_product += outside < 0.5 ? std::log1p(-outside) : log_inside;
      if (outside > 1e-12) cut_slabs_.push_back(static_cast<int>(j));
    }
  }
  c.log_p_up = log_min_inside;
  c.log_p_lo = sum_outside < 1.0 ? std::log1p(-sum_outside) : -std::numeric_limits<double>::infinity();
  // P̃: with one cut direction the product is that slab's exact t probability; with several the slabs
  // share the t's scale variable W ~ χ²_ν, so P̃ = E_W[Π_j P_j | W] (Gaussian slabs given W; quadrature in
  // ln W). Where P_up < 1e-6 (residues far outside the box: no posterior weight) P̃ = P_up.
  c.log_p_sampled = cut_slabs_.size() <= 1 ? log_product : log_slab_mixture();
  c.log_p_sampled = std::clamp(c.log_p_sampled, c.log_p_lo, c.log_p_up);
  c.log_marginal = c.log_untruncated + c.log_p_sampled;
  c.valid = std::isfinite(c.log_marginal);
  return c;
}

double ResidueMarginal::log_slab_mixture() const {
  // Given W the slab coordinates are independent normals N(0, ν/W): E_W[Π_j P_j] as a trapezoid rule in
  // y = ln(W/ν), whose density is f(y) = (ν/2)^{ν/2}/Γ(ν/2) · exp(ν/2 · (y − e^y)), sd ≈ √(2/ν). The integrand
  // f(y) Π_j P_j(y) peaks near y₀ = −ln(1 + Σ_j δ_j²/ν), δ_j the distance of the centre from slab j (Gaussian
  // tails e^{−δ²e^y/2} shift the χ² mode), with the same width: 33 nodes over y₀ ± 10 sd, in logs (far
  // outside the box the product underflows). Only the cut slabs enter: leaving out factors ≤ 1 keeps the
  // bound, and the others hold more than 1 − 1e-12 of the t.
  double distance2 = 0.0;
  for (int j : cut_slabs_) {
    const double dist = std::max({0.0, slab_lo_[j], -slab_hi_[j]});
    distance2 += dist * dist;
  }
  const double nu = c_.nu, sd = std::sqrt(2.0 / nu), centre = -std::log1p(distance2 / nu);
  constexpr int kNodes = 33;
  const double step = 20.0 * sd / (kNodes - 1);
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < kNodes; ++i) {
    const double y = centre + sd * (-10.0 + 20.0 * i / (kNodes - 1)), root = std::exp(0.5 * y);  // √(W/ν)
    double term = mixture_log_norm_ + 0.5 * nu * (y - std::exp(y)) + std::log(step);
    for (int j : cut_slabs_) term += log_normal_interval(slab_lo_[j] * root, slab_hi_[j] * root);
    mixture_terms_[static_cast<std::size_t>(i)] = term;
    best = std::max(best, term);
  }
  if (!std::isfinite(best)) return -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (double t : mixture_terms_) sum += std::exp(t - best);
  return best + std::log(sum);
}

double ResidueMarginal::operator()(const double* poles) const {
  // An invalid conditional (a singular M, or bounds that came out NaN) is outside the support: −∞, never NaN,
  // which the sampler's tests (ln L > L*, ln L = −∞) would not catch.
  const ResidueConditional& c = conditional(poles);
  return c.valid ? c.log_marginal : -std::numeric_limits<double>::infinity();
}

}  // namespace admitgen

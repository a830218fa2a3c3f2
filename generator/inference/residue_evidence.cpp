// SPDX-License-Identifier: MIT
#include "inference/residue_evidence.hpp"

#include "core/errors.hpp"
#include "inference/evidence.hpp"
#include "inference/priors.hpp"
#include "model/residue_basis.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

constexpr double kLogTwoPi = 1.8378770664093454836;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Eigenvalues below this fraction of the largest are numerical zeros of M̃ (a direction the data do not see:
/// its residue keeps its prior).
constexpr double kNullEigenvalue = 1e-13;

/// f'(t) and f''(t) of residue_log_integrand (docs/method.md, "The closed-form marginal"):
///   f'  = −K/2 + ½ Σ μ/(μ+v) + ½ S₀/v + ½ Σ c² v/(μ+v)²
///   f'' = −½ Σ μv/(μ+v)² − ½ S₀/v + ½ Σ c² v(μ − v)/(μ+v)³
void derivatives(const ResiduePosterior& c, double t, double& d1, double& d2) {
  const double v = std::exp(t);
  d1 = -0.5 * c.k + 0.5 * c.s0 / v;
  d2 = -0.5 * c.s0 / v;
  for (Eigen::Index j = 0; j < c.mu.size(); ++j) {
    const double mu = c.mu[j], w = 1.0 / (mu + v);
    d1 += 0.5 * mu * w + 0.5 * c.c2[j] * v * w * w;
    d2 += -0.5 * mu * v * w * w + 0.5 * c.c2[j] * v * (mu - v) * w * w * w;
  }
}

/// The mode of f over t by safeguarded Newton steps from the least-squares estimate of σ².
double find_mode(const ResiduePosterior& c, double& curvature) {
  const double p = static_cast<double>(c.mu.size());
  double t = std::log(c.s0 / std::max(c.k - p, 1.0));
  double d1 = 0.0, d2 = 0.0;
  for (int it = 0; it < 100; ++it) {
    derivatives(c, t, d1, d2);
    // f is not concave everywhere in t; where it is not, a unit step uphill.
    const double step = d2 < 0.0 ? std::clamp(-d1 / d2, -2.0, 2.0) : (d1 > 0.0 ? 1.0 : -1.0);
    t += step;
    if (std::abs(step) < 1e-10 * std::max(1.0, std::abs(t))) break;
  }
  derivatives(c, t, d1, d2);
  curvature = d2;
  return t;
}

/// Gauss-Hermite nodes and weights for ∫ e^{−x²} f(x) dx (Golub-Welsch: eigenvalues of the Jacobi matrix
/// of the Hermite polynomials, off-diagonal √(k/2); weights √π times the squared first eigenvector components).
struct GaussHermite {
  std::array<double, kGaussHermiteNodes> x{}, log_w{};
  GaussHermite() {
    Eigen::VectorXd diag = Eigen::VectorXd::Zero(kGaussHermiteNodes), sub(kGaussHermiteNodes - 1);
    for (int k = 1; k < kGaussHermiteNodes; ++k) sub[k - 1] = std::sqrt(0.5 * k);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
    es.computeFromTridiagonal(diag, sub, Eigen::ComputeEigenvectors);
    for (int k = 0; k < kGaussHermiteNodes; ++k) {
      x[static_cast<std::size_t>(k)] = es.eigenvalues()[k];
      const double v0 = es.eigenvectors()(0, k);
      log_w[static_cast<std::size_t>(k)] = 0.5 * std::log(EIGEN_PI) + 2.0 * std::log(std::abs(v0));
    }
  }
};

const GaussHermite& gauss_hermite() {
  static const GaussHermite rule;
  return rule;
}

}  // namespace

double residue_log_integrand(const ResiduePosterior& c, double t) {
  const double v = std::exp(t);
  // Σ ln(1 + μ/v) as the log of a product (one log per call), rescaled before it could overflow.
  double product = 1.0, log_det = 0.0, quadratic = c.s0 / v;
  for (Eigen::Index j = 0; j < c.mu.size(); ++j) {
    product *= 1.0 + c.mu[j] / v;
    if (product > 1e250) {
      log_det += std::log(product);
      product = 1.0;
    }
    quadratic += c.c2[j] / (c.mu[j] + v);
  }
  log_det += std::log(product);
  return -std::log(2.0) - 0.5 * c.k * (kLogTwoPi + t) - 0.5 * log_det - 0.5 * quadratic;
}

double integrate_noise(const ResiduePosterior& c) {
  const double f_mode = residue_log_integrand(c, c.t_mode);
  const double nu = c.k - static_cast<double>(c.mu.size());
  if (nu >= kMinGaussHermiteNu) {
    // t = t* + √2 w x: ∫ e^f dt = √2 w e^{f*} Σ_i w_i e^{f(t_i) − f* + x_i²}.
    // The terms e_i summed as e^max Σ e^{e_i − max}: one exp per node (not a log_add_exp's exp and log1p).
    const GaussHermite& gh = gauss_hermite();
    const double scale = std::sqrt(2.0) * c.t_scale;
    std::array<double, kGaussHermiteNodes> e{};
    for (std::size_t i = 0; i < gh.x.size(); ++i)
      e[i] = gh.log_w[i] + residue_log_integrand(c, c.t_mode + scale * gh.x[i]) - f_mode + gh.x[i] * gh.x[i];
    const double top = *std::max_element(e.begin(), e.end());
    double sum = 0.0;
    for (double ei : e) sum += std::exp(ei - top);
    return f_mode + std::log(scale) + top + std::log(sum);
  }
  // Few data per residue: the integrand is skewed in t (a heavy tail towards large σ). Adaptive Gauss-Kronrod
  // over the span where it is within 60 nats of its mode, found by doubling steps of the Laplace width.
  const auto relative = [&](double t) { return std::exp(residue_log_integrand(c, t) - f_mode); };
  double lo = c.t_mode - 4.0 * c.t_scale, hi = c.t_mode + 4.0 * c.t_scale;
  for (double step = 4.0 * c.t_scale; residue_log_integrand(c, lo) - f_mode > -60.0; step *= 2.0) lo -= step;
  for (double step = 4.0 * c.t_scale; residue_log_integrand(c, hi) - f_mode > -60.0; step *= 2.0) hi += step;
  const double integral = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(relative, lo, hi, 15, 1e-10);
  return f_mode + std::log(integral);
}

ResidueEvidence::ResidueEvidence(const Measurement& data, const Order& order, DataCount count, double admittance_scale)
    : order_(order),
      points_(data.omega(), data.y),
      b_norm2_(data.y.abs2().sum()),
      k_(real_data_count(count, data.size())),
      p_(residue_count(order)),
      scale_(admittance_scale),
      m_(residue_count(order), residue_count(order)),
      g_(residue_count(order)),
      y_(residue_count(order)),
      eigen_(residue_count(order)) {
  ADMITGEN_ENSURE(k_ > 0 && p_ <= kMaxGramResidues, "K = {} real data for {} residues", k_, p_);
  c_.k = k_;
  c_.sd.resize(p_);
}

double ResidueEvidence::operator()(const double* poles) const {
  ResiduePosterior& c = c_;
  if (!gram(poles)) return c.log_evidence;
  // μ and h without the eigenvectors, which only draws need (numerics/eigen_projection.hpp).
  y_ = c.sd.asDiagonal() * g_;
  if (!projection_.compute(m_, y_)) return c.log_evidence;
  c.mu = projection_.eigenvalues();
  c.h = projection_.projections();
  return integrate(c).log_evidence;
}

const ResiduePosterior& ResidueEvidence::posterior(const double* poles) const {
  ResiduePosterior& c = c_;
  if (!gram(poles)) return c;
  eigen_.compute(m_, Eigen::ComputeEigenvectors);
  if (eigen_.info() != Eigen::Success) return c;
  c.mu = eigen_.eigenvalues();
  c.v = eigen_.eigenvectors();
  c.h = c.v.transpose() * (c.sd.asDiagonal() * g_);
  return integrate(c);
}

bool ResidueEvidence::gram(const double* poles) const {
  ResiduePosterior& c = c_;
  c.valid = false;
  c.log_evidence = -kInf;
  for (int q = 0; q < order_.q(); ++q)
    if (!(poles[q] > 0.0)) return false;
  for (int s = 0; s < order_.s(); ++s)
    if (!(poles[order_.q() + 2 * s] > 0.0)) return false;
  residue_gram(points_, order_.q(), order_.s(), poles, m_.data(), g_.data());
  gaussian_residue_scales(order_, poles, scale_, c.sd.data());
  // M̃ = D M D and D g: the data's Gram matrix in units of the prior (docs/method.md).
  m_ = c.sd.asDiagonal() * m_ * c.sd.asDiagonal();
  return m_.allFinite();
}

const ResiduePosterior& ResidueEvidence::integrate(ResiduePosterior& c) const {
  const double mu_max = c.mu.maxCoeff();
  c.c2.resize(p_);
  double explained = 0.0;
  for (int j = 0; j < p_; ++j) {
    if (!(c.mu[j] > kNullEigenvalue * mu_max)) {
      c.mu[j] = 0.0;
      c.c2[j] = 0.0;
      continue;
    }
    c.c2[j] = c.h[j] * c.h[j] / c.mu[j];
    explained += c.c2[j];
  }
  c.s0 = std::max(b_norm2_ - explained, 1e-300);
  double curvature = 0.0;
  c.t_mode = find_mode(c, curvature);
  if (!(curvature < 0.0) || !std::isfinite(c.t_mode)) return c;
  c.t_scale = 1.0 / std::sqrt(-curvature);
  c.log_evidence = integrate_noise(c);
  c.valid = std::isfinite(c.log_evidence);
  if (!c.valid) c.log_evidence = -kInf;
  return c;
}

Eigen::VectorXd draw_residues(const ResiduePosterior& c, Rng& rng, double* sigma2) {
  ADMITGEN_ENSURE(c.valid, "residue draw from an invalid conditional");
  // t by inversion of the CDF tabulated on a uniform grid (the density linear between nodes).
  const double lo = c.t_mode - kNoiseGridWidths * c.t_scale, step = 2.0 * kNoiseGridWidths * c.t_scale / (kNoiseGridPoints - 1);
  const double f_mode = residue_log_integrand(c, c.t_mode);
  std::array<double, kNoiseGridPoints> density{}, cdf{};
  for (int i = 0; i < kNoiseGridPoints; ++i)
    density[static_cast<std::size_t>(i)] = std::exp(residue_log_integrand(c, lo + step * i) - f_mode);
  for (std::size_t i = 1; i < cdf.size(); ++i) cdf[i] = cdf[i - 1] + 0.5 * (density[i - 1] + density[i]);
  const double u = rng.uniform() * cdf.back();
  const std::size_t i = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin()), cdf.size() - 1);
  // Within cell [i−1, i] the density is linear, d(x) = d0 + (d1 − d0) x; solve ∫₀ˣ d = u − cdf[i−1].
  const double d0 = density[i - 1], d1 = density[i], need = (u - cdf[i - 1]);
  const double slope = d1 - d0;
  double x = 0.5;
  if (std::abs(slope) > 1e-12 * std::max(d0, d1)) {
    x = (-d0 + std::sqrt(std::max(0.0, d0 * d0 + 2.0 * slope * need))) / slope;
  } else if (d0 > 0.0) {
    x = need / d0;
  }
  const double t = lo + step * (static_cast<double>(i - 1) + std::clamp(x, 0.0, 1.0));
  const double v = std::exp(t);
  if (sigma2 != nullptr) *sigma2 = v;
  Eigen::VectorXd z(c.mu.size());
  for (Eigen::Index j = 0; j < z.size(); ++j) {
    const double w = 1.0 / (c.mu[j] + v);
    z[j] = c.h[j] * w + std::sqrt(v * w) * rng.normal();
  }
  return c.sd.asDiagonal() * (c.v * z);
}

Eigen::VectorXd least_squares_residues(const ResiduePosterior& c) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(c.mu.size());
  for (Eigen::Index j = 0; j < z.size(); ++j)
    if (c.mu[j] > 0.0) z[j] = c.h[j] / c.mu[j];
  return c.sd.asDiagonal() * (c.v * z);
}

}  // namespace admitgen

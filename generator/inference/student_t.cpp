// SPDX-License-Identifier: MIT
#include "inference/student_t.hpp"

#include "core/errors.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>

namespace admitgen {
namespace {

// Double precision throughout (Boost's default promotes to long double, several times slower).
using Policy = boost::math::policies::policy<boost::math::policies::underflow_error<boost::math::policies::ignore_error>,
                                             boost::math::policies::promote_double<false>>;
using StudentT = boost::math::students_t_distribution<double, Policy>;

double gamma_draw(double shape, Rng& rng) {
  if (shape < 1.0) {
    double u = rng.uniform();
    while (u <= 0.0) u = rng.uniform();
    return gamma_draw(shape + 1.0, rng) * std::pow(u, 1.0 / shape);
  }
  // Marsaglia & Tsang (2000), "A simple method for generating gamma variables", for shape ≥ 1.
  const double d = shape - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
  for (;;) {
    const double x = rng.normal();
    const double v = std::pow(1.0 + c * x, 3);
    if (v <= 0.0) continue;
    const double u = rng.uniform();
    if (u > 0.0 && std::log(u) < 0.5 * x * x + d - d * v + d * std::log(v)) return d * v;
  }
}

}  // namespace

double student_t_upper_tail(double nu, double z) {
  return boost::math::cdf(boost::math::complement(StudentT(nu), z));
}

double student_t_negligible_tail(double nu) {
  return boost::math::quantile(boost::math::complement(StudentT(nu), 1e-16));
}

StudentTail::StudentTail(double nu)
    : nu_(nu),
      z_neg_(student_t_negligible_tail(nu)),
      log_density_constant_(std::lgamma(0.5 * (nu + 1.0)) - std::lgamma(0.5 * nu) - 0.5 * std::log(nu * boost::math::constants::pi<double>())) {
  if (z_neg_ > 64.0) return;
  const StudentT t(nu);
  const int nodes = static_cast<int>(std::ceil(z_neg_ / step_)) + 2;
  for (int i = 0; i < nodes; ++i) {
    const double z = i * step_;
    const double q = boost::math::cdf(boost::math::complement(t, z));
    log_q_.push_back(std::log(q));
    slope_.push_back(-boost::math::pdf(t, z) / q);
  }
}

double StudentTail::upper(double z) const {
  if (z >= z_neg_) return 0.0;
  if (log_q_.empty()) return student_t_upper_tail(nu_, z);
  const double x = z / step_;
  const auto i = static_cast<std::size_t>(x);
  const double u = x - static_cast<double>(i);
  // Cubic Hermite basis on [z_i, z_i+1] with slopes scaled by the step.
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  return std::exp(h00 * log_q_[i] + h10 * step_ * slope_[i] + h01 * log_q_[i + 1] + h11 * step_ * slope_[i + 1]);
}

double StudentTail::log_upper_bound(double z) const {
  if (z < z_neg_ || !(nu_ > 1.0)) return std::log(upper(std::max(z, 0.0)));
  const double log_f = log_density_constant_ - 0.5 * (nu_ + 1.0) * std::log1p(z * z / nu_);
  return log_f + std::log((nu_ + z * z) / ((nu_ - 1.0) * z));
}

double chi_square_draw(double nu, Rng& rng) { return 2.0 * gamma_draw(0.5 * nu, rng); }

double truncated_student_t_draw(double nu, double a, double b, Rng& rng) {
  ADMITGEN_ENSURE(a <= b, "interval [{}, {}]", a, b);
  if (a > 0.0) return -truncated_student_t_draw(nu, -b, -a, rng);  // mirror: work with lower tails
  const StudentT t(nu);
  const double fa = boost::math::cdf(t, a), fb = boost::math::cdf(t, b);
  if (!(fb > fa)) return a + (b - a) * rng.uniform();  // interval of no resolvable mass: uniform on it
  const double u = fa + (fb - fa) * rng.uniform();
  if (u <= 0.0) return a;
  return std::clamp(boost::math::quantile(t, std::min(u, 1.0 - 1e-16)), a, b);
}

}  // namespace admitgen

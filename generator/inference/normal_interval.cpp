// SPDX-License-Identifier: MIT
#include "inference/normal_interval.hpp"

#include <boost/math/special_functions/erf.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

/// Upper tail of the standard normal, Q(x) = P(Z > x), its logarithm and its inverse.
double normal_upper(double x) { return 0.5 * std::erfc(x / std::sqrt(2.0)); }
double log_normal_upper(double x) {
  if (x < 30.0) return std::log(normal_upper(x));
  const double x2 = x * x;
  return -0.5 * x2 - std::log(x) - 0.91893853320467274 + std::log1p(-1.0 / x2 + 3.0 / (x2 * x2));
}
// In double throughout: Boost's default promotes to long double, several times slower for no accuracy the
// draws need (the result is a double either way).
using DoublePolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
double normal_upper_inverse(double q) { return std::sqrt(2.0) * boost::math::erfc_inv(2.0 * q, DoublePolicy()); }

}  // namespace

double log_normal_interval(double a, double b) {
  if (b <= 0.0) return log_normal_interval(-b, -a);
  if (a > 0.0) {
    const double la = log_normal_upper(a);
    const double lb = std::isfinite(b) ? log_normal_upper(b) : -std::numeric_limits<double>::infinity();
    return la + std::log1p(-std::exp(lb - la));
  }
  const double outside = (std::isfinite(a) ? normal_upper(-a) : 0.0) + (std::isfinite(b) ? normal_upper(b) : 0.0);
  return std::log1p(-outside);
}

double normal_interval_draw(double l, double h, double uniform, double& z) {
  // z = Φ⁻¹(Φ(l) + u(Φ(h) − Φ(l))) in every branch, so z rises with u whichever branch computes it.
  if (h <= 0.0) {  // mirror to the right of 0 (u → 1 − u keeps z rising with u)
    const double log_p = normal_interval_draw(-h, -l, 1.0 - uniform, z);
    z = -z;
    return log_p;
  }
  if (l >= 0.0) {
    const double ql = normal_upper(l), qh = normal_upper(h), p = ql - qh;
    if (!(p > 0.0)) {  // beyond double precision
      z = l;
      return log_normal_interval(l, h);
    }
    z = std::clamp(normal_upper_inverse(std::max(qh + (1.0 - uniform) * p, 1e-300)), l, h);  // Q(z) = Q(h) + (1 − u)p
    return std::log(p);
  }
  const double below = normal_upper(-l), above = normal_upper(h), p = 1.0 - below - above;
  const double v = below + uniform * p;  // Φ(z)
  z = std::clamp(v < 0.5 ? -normal_upper_inverse(std::max(v, 1e-300)) : normal_upper_inverse(std::max(1.0 - v, 1e-300)),
                 l, h);
  return std::log1p(-(below + above));
}

}  // namespace admitgen

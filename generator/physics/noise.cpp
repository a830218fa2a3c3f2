// SPDX-License-Identifier: MIT
#include "physics/noise.hpp"

#include "core/errors.hpp"

#include <cmath>

namespace admitgen {

Eigen::ArrayXcd complex_gaussian_noise(const Eigen::ArrayXd& std_per_point, Rng& rng) {
  Eigen::ArrayXcd n(std_per_point.size());
  const double per_component = 1.0 / std::sqrt(2.0);
  for (Eigen::Index i = 0; i < n.size(); ++i) {
    const double sigma = std_per_point[i];
    ADMITGEN_ENSURE(std::isfinite(sigma) && sigma >= 0.0, "noise std {} at point {}", sigma, i);
    const double re = rng.normal();
    const double im = rng.normal();
    n[i] = {sigma * per_component * re, sigma * per_component * im};
  }
  return n;
}

Eigen::ArrayXd heteroscedastic_std(double sigma, double scale, const Air& air, double spacing_m,
                                   const Eigen::ArrayXd& f_hz) {
  const Eigen::ArrayXd std = heteroscedastic_std(sigma, scale, microphone_sin_ks(air, spacing_m, f_hz));
  for (Eigen::Index i = 0; i < std.size(); ++i)
    if (!std::isfinite(std[i]))
      throw InputError(fmt::format("heteroscedastic_noise: {} Hz sits where sin(ks) = 0 (s = {} m): the two-microphone "
                                   "method cannot measure there; change {} or {}",
                                   f_hz[i], spacing_m, setting("band"), setting("tube.spacing_m")));
  return std;
}

Eigen::ArrayXd microphone_sin_ks(const Air& air, double spacing_m, const Eigen::ArrayXd& f_hz) {
  return (2.0 * EIGEN_PI * f_hz * spacing_m / air.c0).sin().abs();
}

Eigen::ArrayXd heteroscedastic_std(double sigma, double scale, const Eigen::ArrayXd& sin_ks) {
  return sigma * (1.0 + (scale / sin_ks).square()).sqrt();
}

}  // namespace admitgen

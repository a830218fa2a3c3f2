// SPDX-License-Identifier: MIT
/// @file
/// Small synthetic data sets for sampler tests: a known multipole model at log-spaced frequencies
/// plus complex Gaussian noise of std σ (σ²/2 per component), from a recorded seed.
#pragma once

#include "core/rng.hpp"
#include "data/measurement.hpp"
#include "model/multipole.hpp"

#include <cmath>

namespace admitgen::test {

inline Measurement synthetic(const Order& order, const Eigen::VectorXd& theta, int points, double f_lo, double f_hi,
                             double sigma, std::uint64_t seed) {
  Measurement m;
  m.path = "synthetic";
  m.f_hz = Eigen::ArrayXd::LinSpaced(points, std::log(f_lo), std::log(f_hi)).exp();
  m.y = evaluate_multipole(order, theta, m.omega());
  Rng rng(seed);
  const double per_component = sigma / std::sqrt(2.0);
  for (Eigen::Index i = 0; i < m.size(); ++i) m.y[i] += std::complex<double>(rng.normal(), rng.normal()) * per_component;
  return m;
}

}  // namespace admitgen::test

// SPDX-License-Identifier: MIT
// Noise of docs/cli.md: complex Gaussian with E|n|² = σ² (σ²/2 per component), drawn from core/rng.hpp,
// and the heteroscedastic std σ √(1 + (scale/|sin ks|)²).
#include "physics/noise.hpp"

#include <doctest/doctest.h>

#include <cmath>

namespace admitgen {
namespace {

TEST_CASE("complex Gaussian noise: E|n|^2 = sigma^2, sigma^2/2 per component, uncorrelated, deterministic") {
  // N = 40 000 draws: |n|²/σ² is Exp(1) (std 1), Re² /(σ²/2) is χ²₁ (std √2), so 4-sigma bounds on the
  // sample means are 4/√N = 2 % and 4√2/√N = 2.8 %; the Re-Im correlation has std 1/√N: bound 4/√N.
  const int n = 40000;
  const double sigma = 0.1;
  Rng rng(42);
  const Eigen::ArrayXcd noise = complex_gaussian_noise(Eigen::ArrayXd::Constant(n, sigma), rng);
  const double power = noise.abs2().mean() / (sigma * sigma);
  const double re = noise.real().square().mean() / (sigma * sigma / 2.0);
  const double im = noise.imag().square().mean() / (sigma * sigma / 2.0);
  const double corr = (noise.real() * noise.imag()).mean() / (sigma * sigma / 2.0);
  CHECK(std::abs(power - 1.0) <= 4.0 / std::sqrt(n));
  CHECK(std::abs(re - 1.0) <= 4.0 * std::sqrt(2.0) / std::sqrt(n));
  CHECK(std::abs(im - 1.0) <= 4.0 * std::sqrt(2.0) / std::sqrt(n));
  CHECK(std::abs(corr) <= 4.0 / std::sqrt(n));

  Rng again(42), other(43);
  CHECK((complex_gaussian_noise(Eigen::ArrayXd::Constant(n, sigma), again) == noise).all());
  CHECK(!(complex_gaussian_noise(Eigen::ArrayXd::Constant(n, sigma), other) == noise).all());
}

TEST_CASE("heteroscedastic std: sigma sqrt(1 + (scale/|sin ks|)^2)") {
  const Air air = Air::at_celsius(20.0);
  const double s = 0.05;
  // At ks = π/2 (f = c/4s) the factor is √(1 + scale²); at ks = π/6 it is √(1 + 4 scale²).
  const Eigen::ArrayXd f = (Eigen::ArrayXd(2) << air.c0 / (4.0 * s), air.c0 / (12.0 * s)).finished();
  const Eigen::ArrayXd std = heteroscedastic_std(0.01, 0.5, air, s, f);
  CHECK(std[0] == doctest::Approx(0.01 * std::sqrt(1.25)).epsilon(1e-14));
  CHECK(std[1] == doctest::Approx(0.01 * std::sqrt(2.0)).epsilon(1e-14));
  CHECK((heteroscedastic_std(0.01, 0.0, air, s, f) == 0.01).all());
}

}  // namespace
}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "inference/likelihood.hpp"

#include "core/errors.hpp"
#include "model/multipole.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen {

DataCount parse_data_count(const std::string& text) {
  if (text == "2N") return DataCount::two_per_point;
  if (text == "N") return DataCount::one_per_point;
  throw InputError(fmt::format("{} '{}': expected 2N (default) or N (the paper's count)", setting("data_count"), text));
}

std::string describe(DataCount count) {
  return count == DataCount::two_per_point ? "marginal-gaussian, K = 2N (eq. 10, Jeffreys-marginalised noise)"
                                           : "marginal-gaussian, K = N (eq. 10 as the paper's text reads)";
}

int real_data_count(DataCount count, Eigen::Index points) {
  return static_cast<int>(count == DataCount::two_per_point ? 2 * points : points);
}

Likelihood::Likelihood(const Measurement& data, const Order& order, DataCount count)
    : order_(order),
      grid_(data.omega()),
      d_re_(data.y.real()),
      d_im_(data.y.imag()),
      k_(real_data_count(count, data.size())),
      constant_(std::lgamma(0.5 * k_) - std::log(2.0) - 0.5 * k_ * std::log(EIGEN_PI)) {}

double Likelihood::sum_squared_residual(const double* theta) const {
  grid_.evaluate(order_, theta, re_, im_);
  return (d_re_ - re_).square().sum() + (d_im_ - im_).square().sum();
}

double Likelihood::operator()(const double* theta) const {
  const double e = std::max(sum_squared_residual(theta), 1e-300);
  return constant_ - 0.5 * k_ * std::log(e);
}

}  // namespace admitgen

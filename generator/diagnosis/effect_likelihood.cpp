// SPDX-License-Identifier: MIT
#include "diagnosis/effect_likelihood.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <limits>

namespace admitgen::diagnosis {

EffectLikelihood::EffectLikelihood(Eigen::ArrayXcd y_real)
    : y_(std::move(y_real)), marginal_(2.0 * static_cast<double>(y_.size())) {}

double EffectLikelihood::operator()(const EffectPrediction& p) const {
  ADMITGEN_ENSURE(p.y.size() == y_.size(), "prediction has {} points, data {}", p.y.size(), y_.size());
  double e_w = 0.0, log_shape = 0.0;
  if (p.noise_shape.size() == 0) {
    e_w = (y_ - p.y).abs2().sum();
  } else {
    ADMITGEN_ENSURE(p.noise_shape.size() == y_.size(), "noise shape has {} points, data {}", p.noise_shape.size(),
                    y_.size());
    e_w = ((y_ - p.y).abs2() / p.noise_shape.square()).sum();
    log_shape = 2.0 * p.noise_shape.log().sum();
  }
  if (!std::isfinite(e_w) || !std::isfinite(log_shape)) return -std::numeric_limits<double>::infinity();
  return marginal_(e_w) - log_shape;
}

}  // namespace admitgen::diagnosis

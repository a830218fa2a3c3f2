// SPDX-License-Identifier: MIT
#include "inference/slice_step.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen {

SliceStep::SliceStep(int dim, const PriorTransformFn& transform, const LogLikelihoodFn& log_likelihood)
    : dim_(dim),
      transform_(transform),
      log_likelihood_(log_likelihood),
      direction_(dim),
      trial_(dim),
      theta_trial_(dim) {}

bool SliceStep::inside(const Eigen::VectorXd& u, double log_l_min, double& log_l, long& calls) {
  if ((u.array() < 0.0).any() || (u.array() >= 1.0).any()) return false;
  transform_(u.data(), theta_trial_.data());
  ++calls;
  log_l = log_likelihood_(theta_trial_.data());
  return log_l > log_l_min;
}

long SliceStep::move(Eigen::VectorXd& u, Eigen::VectorXd& theta, double& log_l, double log_l_min, int slices,
                     Rng& rng) {
  constexpr int kMaxSteps = 1000;  // stepping-out cap per side; unit cube bounds it long before
  ADMITGEN_ENSURE(axes_ != nullptr && scale_ != nullptr && axes_->rows() == dim_, "slice axes not set");
  long calls = 0;
  long expansions = 0, contractions = 0;
  for (int k = 0; k < slices; ++k) {
    for (int i = 0; i < dim_; ++i) direction_[i] = rng.normal();
    direction_ = *scale_ * (*axes_ * direction_.normalized());
    // Initial bracket of unit width (in units of the direction), randomly placed around 0.
    double left = -rng.uniform(), right = left + 1.0, trial_log_l = 0.0;
    for (int step = 0; step < kMaxSteps; ++step, --left, ++expansions) {
      trial_ = u + left * direction_;
      if (!inside(trial_, log_l_min, trial_log_l, calls)) break;
    }
    for (int step = 0; step < kMaxSteps; ++step, ++right, ++expansions) {
      trial_ = u + right * direction_;
      if (!inside(trial_, log_l_min, trial_log_l, calls)) break;
    }
    // Shrinkage: sample uniformly in the bracket, pull the violated end in until inside.
    for (;;) {
      const double t = left + rng.uniform() * (right - left);
      trial_ = u + t * direction_;
      if (inside(trial_, log_l_min, trial_log_l, calls)) {
        u = trial_;
        theta = theta_trial_;
        log_l = trial_log_l;
        break;
      }
      ++contractions;
      (t < 0.0 ? left : right) = t;
      if (right - left < 1e-15) break;  // degenerate slice: keep the current point (still valid)
    }
  }
  // Adapt the width: more expansions than contractions means the bracket is too short.
  const double ratio = static_cast<double>(expansions + 1) / static_cast<double>(contractions + 1);
  *scale_ *= std::clamp(ratio, 0.25, 8.0);
  return calls;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The constrained-prior step of nested sampling: a short chain of 1-D slice-sampling moves (Neal 2003,
/// stepping out and shrinkage) inside {u ∈ [0,1]^d : L(θ(u)) > L*}, along random directions drawn
/// isotropically in the space whitened by the live points' covariance (PolyChord; dynesty "rslice").
/// Each 1-D move leaves the uniform distribution on the constrained region invariant for any width,
/// so the width only affects efficiency; it adapts between replacements so that stepping-out and
/// shrinking happen about equally often (dynesty's rule). The width belongs to the whitening it is used
/// with (one per cluster of live points): a cluster whose covariance spans several narrow modes needs a
/// width far below one that is a single mode, and a shared width would make the second step out by
/// hundreds of calls per slice.
#pragma once

#include "core/rng.hpp"
#include "inference/nested_sampler.hpp"

#include <Eigen/Core>

namespace admitgen {

class SliceStep {
 public:
  SliceStep(int dim, const PriorTransformFn& transform, const LogLikelihoodFn& log_likelihood);

  /// Sets the whitening matrix (lower Cholesky factor of the live points' covariance in u) and the width
  /// in its units, adapted in place by each move.
  void set_axes(const Eigen::MatrixXd& cholesky, double& scale) {
    axes_ = &cholesky;
    scale_ = &scale;
  }

  /// Moves (u, θ, ln L) by `slices` slice moves under ln L > log_l_min; returns calls made.
  long move(Eigen::VectorXd& u, Eigen::VectorXd& theta, double& log_l, double log_l_min, int slices, Rng& rng);

 private:
  /// ln L at u if u is inside the unit cube and above the bound (θ written to theta_trial_).
  bool inside(const Eigen::VectorXd& u, double log_l_min, double& log_l, long& calls);

  int dim_;
  const PriorTransformFn& transform_;
  const LogLikelihoodFn& log_likelihood_;
  const Eigen::MatrixXd* axes_ = nullptr;
  double* scale_ = nullptr;
  Eigen::VectorXd direction_, trial_, theta_trial_;
};

}  // namespace admitgen

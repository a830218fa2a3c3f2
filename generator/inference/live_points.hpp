// SPDX-License-Identifier: MIT
/// @file
/// The live points of a nested-sampling run (inference/nested_sampler.hpp) and a point proposed to replace
/// the one that died. The proposals (inference/proposal.hpp) read the first and write the second.
#pragma once

#include <Eigen/Core>

namespace admitgen {

/// The n live points as columns: position in the unit cube, θ, ln L.
struct LivePoints {
  Eigen::MatrixXd u, theta;
  Eigen::VectorXd log_l;
};

/// A replacement above the contour: its position in the cube, θ, ln L, and the cluster of live points
/// (inference/live_point_clusters.hpp) it joins.
struct ProposedPoint {
  Eigen::VectorXd u, theta;
  double log_l = 0.0;
  int cluster = 0;
};

}  // namespace admitgen

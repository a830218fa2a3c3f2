// SPDX-License-Identifier: MIT
/// @file
/// Clusters of live points, each with its own whitening axes, so that slice directions stay local to
/// a mode when the live set splits into several (mirror modes of an unreduced prior, competing pole
/// configurations). Recursive bisection by 2-means in the parent's whitened coordinates; a split is
/// kept when the children's covariance volumes √det Σ sum to less than half the parent's — the
/// ellipsoid-decomposition criterion of MultiNest (Feroz, Hobson & Bridges 2009, §5.2), which a single
/// uniformly filled ellipsoid never meets (its two halves sum to about the parent's volume).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace admitgen {

struct LivePointClusters {
  std::vector<int> label;             ///< cluster of each live point (column)
  std::vector<Eigen::MatrixXd> axes;  ///< lower Cholesky factor of each cluster's covariance
};

/// Clusters the columns of `u` (dim × n). Children must keep at least `min_size` points; at most
/// `max_clusters` clusters. Deterministic (no random initialisation).
LivePointClusters cluster_live_points(const Eigen::MatrixXd& u, int min_size, int max_clusters);

/// Lower Cholesky factor of the sample covariance of the columns of `u`, with a tiny ridge.
Eigen::MatrixXd covariance_axes(const Eigen::MatrixXd& u);

}  // namespace admitgen

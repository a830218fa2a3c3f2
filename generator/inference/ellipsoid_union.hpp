// SPDX-License-Identifier: MIT
/// @file
/// Uniform draws inside the union of ellipsoids that bound the clusters of live points: the constrained
/// step of MultiNest (Feroz, Hobson & Bridges 2009, §5.1-5.3) and of dynesty's "multi" bound (Speagle
/// 2020, §4.1). In a few dimensions a draw from the union that lands above the likelihood contour is an
/// independent draw from the constrained prior after one or two likelihood calls, where a slice chain
/// needs 3 + dim slices of several calls each (docs/method.md, "Sampler and evidence error").
///
/// Each cluster k (inference/live_point_clusters.hpp) is bounded by E_k = {x : |L_k⁻¹(x − μ_k)| ≤ f·s_k}:
/// μ_k and L_k the mean and the Cholesky factor of its members' covariance, s_k the largest whitened
/// distance of a member, f = e^{ln(enlarge)/d} so that E_k's volume is `enlarge` times that of the tightest
/// ellipsoid of this shape holding every member (the members lie inside the contour, not on it).
/// A draw picks k with probability V_k/ΣV, a point x uniform in E_k, and keeps it with probability
/// 1/m(x), m(x) the number of ellipsoids holding x: the kept points are uniform on the union (Feroz et al.
/// 2009, §5.3). The union bounds the contour only approximately; that is the method's assumption, which
/// the enlargement covers and the evidence tests check (docs/method.md).
#pragma once

#include "core/rng.hpp"
#include "inference/live_point_clusters.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen {

class EllipsoidUnion {
 public:
  /// Bounds every cluster of the columns of `u` (labels and Cholesky factors from `clusters`).
  EllipsoidUnion(const Eigen::MatrixXd& u, const LivePointClusters& clusters, double enlarge);

  /// One draw: false when the multiplicity test rejected it; otherwise x is uniform on the union and
  /// `cluster` is the ellipsoid it was drawn in.
  bool draw(Rng& rng, Eigen::VectorXd& x, int& cluster) const;

  /// ln Σ V_k (unit ball volume left out), for diagnostics and tests.
  double log_volume() const { return log_volume_; }
  std::size_t size() const { return ellipsoids_.size(); }

  /// Whether x lies in ellipsoid k.
  bool contains(std::size_t k, const Eigen::VectorXd& x) const;

 private:
  struct Ellipsoid {
    Eigen::VectorXd centre;
    Eigen::MatrixXd axes;  ///< radius · L_k (lower triangular): x = centre + axes·z, |z| ≤ 1
    double log_volume = 0.0;
  };
  std::vector<Ellipsoid> ellipsoids_;
  std::vector<double> cumulative_;  ///< V_1 + … + V_k over ΣV
  double log_volume_ = 0.0;
  mutable Eigen::VectorXd z_;
};

}  // namespace admitgen

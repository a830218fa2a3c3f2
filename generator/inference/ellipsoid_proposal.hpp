// SPDX-License-Identifier: MIT
/// @file
/// The ellipsoid proposal (inference/proposal.hpp): uniform draws in the bounding ellipsoid of the live points
/// (inference/ellipsoid_union.hpp), each kept when it lies above the contour. It serves only while the live
/// points form one cluster: where they split (several modes, or a spare pole trading roles with another across
/// a curved region) a missed corner of the contour would lose posterior mass for good, while a slice chain
/// from a live point reaches wherever live points are (docs/method.md, "Sampler and evidence error").
///
/// Its cost since the last covariance update is kept so that the sampler can ask whether it still pays: the
/// likelihood calls of its draws, the draws rejected without a call (outside the cube or the canonical domain
/// of a folded model, which can be most of an ellipsoid that straddles a fold's seam) at kDrawsPerCall of them
/// per call, and the calls of the slice chain that replaced a point after it gave up (charge()).
#pragma once

#include "inference/ellipsoid_union.hpp"
#include "inference/model.hpp"
#include "inference/proposal.hpp"

#include <optional>

namespace admitgen {

class EllipsoidProposal final : public Proposal {
 public:
  /// Rejected draws (normal deviates, a triangular product, the fold) that cost as much as one likelihood
  /// call: a call at the smallest data sets here (60 points, 3 residues) takes about 20 times a draw at
  /// dim 12; larger data make calls dearer, so this undercounts the calls' share, never the draws'.
  static constexpr long kDrawsPerCall = 20;

  /// `enlarge`: volume of the bounding ellipsoid over the tightest one of its shape that holds the live points.
  EllipsoidProposal(const Model& model, double enlarge);

  /// Bounds the live points when they form one cluster (else the proposal is unavailable until the next
  /// update), and restarts the cost count.
  void update(const LivePoints& live, const LivePointClusters& clusters) override;
  /// Draws until a point of the canonical domain lies above the contour; gives up after `max_calls` calls or
  /// kDrawsPerCall times as many draws.
  bool propose(const LivePoints& live, Eigen::Index worst, double log_l_min, long max_calls, Rng& rng,
               ProposedPoint& out, long& calls) override;

  /// Whether the ellipsoid exists and its replacements since the update cost no more calls each than a
  /// slice chain's `slice_calls`.
  bool pays(double slice_calls) const;
  /// Adds the calls of the slice chain that replaced a point after this proposal gave up.
  void charge(long calls) { cost_ += static_cast<double>(calls); }

 private:
  const Model& model_;
  double enlarge_;
  std::optional<EllipsoidUnion> bounds_;
  double cost_ = 0.0;    ///< calls (rejected draws weighted by 1/kDrawsPerCall) since the last update
  long replacements_ = 0;  ///< proposals made since the last update
  Eigen::VectorXd folded_;
};

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The constrained step of nested sampling behind one interface, as dynesty's samplers are (Speagle 2020,
/// §4): a proposal turns the live points into a new point drawn from the prior above the likelihood
/// contour. Two exist: a slice chain from a live point (inference/slice_proposal.hpp), which always
/// succeeds, and uniform draws from the live points' bounding ellipsoids (inference/ellipsoid_proposal.hpp),
/// which may give up within a call budget. Which one replaces a point is the rule in nested_sampler.cpp.
#pragma once

#include "core/rng.hpp"
#include "inference/live_point_clusters.hpp"
#include "inference/live_points.hpp"

namespace admitgen {

class Proposal {
 public:
  Proposal() = default;
  Proposal(const Proposal&) = delete;
  Proposal& operator=(const Proposal&) = delete;
  virtual ~Proposal() = default;

  /// The live points and their clusters at a covariance update; `clusters` outlives the next update.
  virtual void update(const LivePoints& live, const LivePointClusters& clusters) = 0;

  /// A point above `log_l_min` in `out`, replacing live point `worst`; false when the proposal gave up
  /// within `max_calls` likelihood calls. Adds the calls it made to `calls`.
  virtual bool propose(const LivePoints& live, Eigen::Index worst, double log_l_min, long max_calls, Rng& rng,
                       ProposedPoint& out, long& calls) = 0;
};

}  // namespace admitgen

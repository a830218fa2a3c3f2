// SPDX-License-Identifier: MIT
#include "inference/ellipsoid_proposal.hpp"

#include <algorithm>

namespace admitgen {

EllipsoidProposal::EllipsoidProposal(const Model& model, double enlarge)
    : model_(model), enlarge_(enlarge), folded_(model.dim()) {}

void EllipsoidProposal::update(const LivePoints& live, const LivePointClusters& clusters) {
  if (clusters.axes.size() == 1) bounds_.emplace(live.u, clusters, enlarge_);
  else bounds_.reset();
  cost_ = 0.0;
  replacements_ = 0;
}

bool EllipsoidProposal::pays(double slice_calls) const {
  return bounds_ && cost_ <= slice_calls * static_cast<double>(replacements_ + 1);
}

bool EllipsoidProposal::propose(const LivePoints& /*live*/, Eigen::Index /*worst*/, double log_l_min,
                                long max_calls, Rng& rng, ProposedPoint& out, long& calls) {
  // A draw outside the unit cube or off the canonical domain (the fold's fixed points; folding it instead
  // would double the density where an ellipsoid crosses a seam) is rejected without a likelihood call.
  const long max_draws = kDrawsPerCall * max_calls;
  long made = 0, draws = 0;
  bool found = false;
  out.u.resize(model_.dim());
  out.theta.resize(model_.dim());
  for (; draws < max_draws && made < max_calls && !found; ++draws) {
    if (!bounds_->draw(rng, out.u, out.cluster)) continue;
    if ((out.u.array() < 0.0).any() || (out.u.array() >= 1.0).any()) continue;
    if (model_.fold) {
      folded_ = out.u;
      model_.fold(folded_.data());
      if (folded_ != out.u) continue;
    }
    model_.prior_transform(out.u.data(), out.theta.data());
    out.log_l = model_.log_likelihood(out.theta.data());
    ++made;
    found = out.log_l > log_l_min;
  }
  calls += made;
  cost_ += static_cast<double>(made) + static_cast<double>(draws - made) / kDrawsPerCall;
  ++replacements_;
  return found;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "inference/slice_proposal.hpp"

#include "core/errors.hpp"

#include <cmath>
#include <cstdint>

namespace admitgen {

SliceProposal::SliceProposal(const Model& model, int slices)
    : model_(model),
      slices_(slices),
      mean_calls_(4.0 * slices),
      step_(model.dim(), model.prior_transform, model.log_likelihood) {}

void SliceProposal::update(const LivePoints& /*live*/, const LivePointClusters& clusters) {
  // New clusters need not match old ones: each starts from the geometric mean of the previous widths and
  // adapts on its own.
  double log_mean = 0.0;
  for (double w : widths_) log_mean += std::log(w);
  const double start = widths_.empty() ? 1.0 : std::exp(log_mean / static_cast<double>(widths_.size()));
  widths_.assign(clusters.axes.size(), start);
  clusters_ = &clusters;
}

bool SliceProposal::propose(const LivePoints& live, Eigen::Index worst, double log_l_min, long /*max_calls*/,
                            Rng& rng, ProposedPoint& out, long& calls) {
  ADMITGEN_ENSURE(clusters_ != nullptr, "slice proposal used before its first update");
  const Eigen::Index n = live.log_l.size();
  Eigen::Index start = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n - 1)));
  if (start >= worst) ++start;
  const auto cluster = static_cast<std::size_t>(clusters_->label[static_cast<std::size_t>(start)]);
  out.cluster = static_cast<int>(cluster);
  out.u = live.u.col(start);
  out.theta = live.theta.col(start);
  out.log_l = live.log_l[start];
  step_.set_axes(clusters_->axes[cluster], widths_[cluster]);
  const long made = step_.move(out.u, out.theta, out.log_l, log_l_min, slices_, rng);
  calls += made;
  mean_calls_ = 0.9 * mean_calls_ + 0.1 * static_cast<double>(made);
  if (model_.fold) {
    model_.fold(out.u.data());
    model_.prior_transform(out.u.data(), out.theta.data());  // same ln L: the likelihood is invariant
  }
  return true;
}

}  // namespace admitgen

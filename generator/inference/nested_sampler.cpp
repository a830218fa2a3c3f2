// SPDX-License-Identifier: MIT
#include "inference/nested_sampler.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "inference/ellipsoid_proposal.hpp"
#include "inference/evidence.hpp"
#include "inference/live_point_clusters.hpp"
#include "inference/live_points.hpp"
#include "inference/slice_proposal.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace admitgen {
namespace {

constexpr double kMinusInf = -std::numeric_limits<double>::infinity();

/// The initial live points, drawn from the prior by rejection of ln L = −∞. That value marks a point
/// outside the support (e.g. a prior truncated to passive models), so the run samples the prior
/// restricted to the support and ln Z is the evidence under that renormalised prior; draws/accepted
/// estimate the support fraction (NestedRun::log_support_fraction).
LivePoints draw_live_points(const Model& model, int n, Rng& rng, NestedRun& run) {
  const int dim = model.dim();
  LivePoints live{Eigen::MatrixXd(dim, n), Eigen::MatrixXd(dim, n), Eigen::VectorXd(n)};
  constexpr long kMaxDrawsPerPoint = 10000;
  long draws = 0;
  for (int i = 0; i < n; ++i) {
    do {
      if (draws >= kMaxDrawsPerPoint * n)
        throw InputError(fmt::format("fewer than 1 in {} prior draws has a finite likelihood (a support this small, "
                                     "e.g. a prior truncated to passive models when almost none of them is, "
                                     "cannot be sampled)",
                                     kMaxDrawsPerPoint));
      for (int k = 0; k < dim; ++k) live.u(k, i) = rng.uniform();
      if (model.fold) model.fold(live.u.col(i).data());
      model.prior_transform(live.u.col(i).data(), live.theta.col(i).data());
      live.log_l[i] = model.log_likelihood(live.theta.col(i).data());
      ++run.calls;
      ++draws;
    } while (live.log_l[i] == kMinusInf);
  }
  run.log_support_fraction = std::log(static_cast<double>(n) / static_cast<double>(draws));
  return live;
}

/// Evidence bookkeeping over the deaths (Skilling 2006, §3-4): X_i = e^{−i/n}, w_i = L_i (X_{i−1} − X_i).
class Compression {
 public:
  explicit Compression(int n) : log_shrink_(-1.0 / n), log_width_factor_(std::log(-std::expm1(log_shrink_))) {}

  /// The worst live point dies: it joins the run with its weight, and X shrinks. Returns its column.
  Eigen::Index kill_worst(const LivePoints& live, NestedRun& run) {
    Eigen::Index worst = 0;
    const double log_l_min = live.log_l.minCoeff(&worst);
    const double log_w = log_l_min + log_x_ + log_width_factor_;  // L_i (X_{i−1} − X_i)
    acc_.add(log_w, log_l_min);
    run.samples.insert(run.samples.end(), live.theta.col(worst).data(), live.theta.col(worst).data() + run.dim);
    run.log_likelihood.push_back(log_l_min);
    run.log_weight.push_back(log_w);
    log_x_ += log_shrink_;
    contour_ = log_l_min;
    return worst;
  }

  NestedStatus status(long iteration, const LivePoints& live, long calls) const {
    const double log_l_max = live.log_l.maxCoeff();
    const double remaining = log_add_exp(acc_.log_z, log_l_max + log_x_) - acc_.log_z;
    return NestedStatus{iteration, acc_.log_z, remaining, calls, log_x_, contour_, log_l_max};
  }

  /// The remaining live points share the last volume X equally (Skilling 2006, §5), in ascending ln L.
  void close(const LivePoints& live, NestedRun& run) {
    std::vector<Eigen::Index> order;
    for (Eigen::Index i = 0; i < live.log_l.size(); ++i)
      if (std::isfinite(live.log_l[i])) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return live.log_l[a] < live.log_l[b]; });
    const double log_share = log_x_ - std::log(static_cast<double>(order.size()));
    for (Eigen::Index i : order) {
      const double log_w = live.log_l[i] + log_share;
      acc_.add(log_w, live.log_l[i]);
      run.samples.insert(run.samples.end(), live.theta.col(i).data(), live.theta.col(i).data() + run.dim);
      run.log_likelihood.push_back(live.log_l[i]);
      run.log_weight.push_back(log_w);
    }
  }

  /// ln Z, the information H and the error √(H/n).
  void finish(int n, NestedRun& run) const {
    run.log_z = acc_.log_z;
    run.information = std::max(acc_.h, 0.0);
    run.log_z_error = std::sqrt(run.information / n);
    run.max_log_likelihood = *std::max_element(run.log_likelihood.begin(), run.log_likelihood.end());
  }

 private:
  EvidenceAccumulator acc_;
  double log_shrink_;        // ln(X_i / X_{i−1})
  double log_width_factor_;  // ln(1 − e^{−1/n})
  double log_x_ = 0.0;       // ln X_{i−1}
  double contour_ = kMinusInf;
};

/// The constrained step (inference/proposal.hpp): the dead point is replaced by a uniform draw from the
/// bounding ellipsoid above the contour (NestedSettings::ellipsoid_draws; inference/ellipsoid_proposal.hpp) or
/// by a slice chain from a surviving live point (inference/slice_proposal.hpp); the new point joins the
/// cluster it came from.
///
/// Which of the two: both give a draw from the constrained prior (the ellipsoid up to how well it covers the
/// contour), so the choice sets the cost. The ellipsoid serves while its likelihood calls per replacement
/// since the last covariance update stay below a slice chain's running mean (EllipsoidProposal::pays); a
/// replacement for which it finds nothing within a slice chain's mean calls moves by slices instead, and those
/// calls are charged to it. Where the contour is nearly ellipsoidal one or two calls replace 3 + dim slices;
/// where it is far from it, slices serve (docs/method.md, "Sampler and evidence error").
class Replacement {
 public:
  Replacement(const Model& model, const NestedSettings& settings)
      : cov_interval_(settings.covariance_interval > 0 ? settings.covariance_interval
                                                       : std::max(1, settings.live / 10)),
        min_cluster_(std::max(2 * model.dim(), 20)),
        slices_(model, settings.slices_per_replacement(model.dim())) {
    if (settings.ellipsoid_draws) ellipsoids_.emplace(model, settings.ellipsoid_enlarge);
  }

  void replace(LivePoints& live, Eigen::Index worst, long iteration, Rng& rng, NestedRun& run) {
    // Clusters need enough points for a covariance: at least 2·dim and 20.
    constexpr int kMaxClusters = 8;
    if (iteration % cov_interval_ == 0) {
      clusters_ = cluster_live_points(live.u, min_cluster_, kMaxClusters);
      slices_.update(live, clusters_);
      if (ellipsoids_) ellipsoids_->update(live, clusters_);
    }
    const double log_l_min = live.log_l[worst];
    const bool bounded = ellipsoids_ && ellipsoids_->pays(slices_.mean_calls());
    const long budget = std::max(1L, std::lround(slices_.mean_calls()));
    if (!bounded || !ellipsoids_->propose(live, worst, log_l_min, budget, rng, point_, run.calls)) {
      long calls = 0;
      slices_.propose(live, worst, log_l_min, budget, rng, point_, calls);
      run.calls += calls;
      if (bounded) ellipsoids_->charge(calls);  // the ellipsoid missed: its replacement cost these too
    }
    clusters_.label[static_cast<std::size_t>(worst)] = point_.cluster;
    live.u.col(worst) = point_.u;
    live.theta.col(worst) = point_.theta;
    live.log_l[worst] = point_.log_l;
  }

 private:
  int cov_interval_, min_cluster_;
  LivePointClusters clusters_;
  SliceProposal slices_;
  std::optional<EllipsoidProposal> ellipsoids_;
  ProposedPoint point_;
};

}  // namespace

double automatic_dlogz(int live) { return 0.01 + 0.001 * (live - 1); }

NestedRun run_nested_sampling(const Model& model, const NestedSettings& settings, const NestedProgressFn& progress,
                              const NestedStopFn& stop) {
  ADMITGEN_ENSURE(model.dim() >= 1, "dimension {}", model.dim());
  ADMITGEN_ENSURE(settings.live >= 2, "live points {}", settings.live);
  Rng rng(settings.seed);
  NestedRun run;
  run.dim = model.dim();
  LivePoints live = draw_live_points(model, settings.live, rng, run);
  Compression compression(settings.live);
  Replacement replacement(model, settings);
  run.stopped_by = "max_iterations";
  for (long it = 0; it < settings.max_iterations; ++it) {
    const Eigen::Index worst = compression.kill_worst(live, run);
    run.iterations = it + 1;
    const NestedStatus status = compression.status(it, live, run.calls);
    if (progress && it % 100 == 0) progress(status);
    const bool converged = status.remaining < settings.stop_dlogz();
    if (converged || (stop && stop(status))) {
      run.stopped_by = converged ? "dlogz" : "early_stop";
      live.log_l[worst] = kMinusInf;  // already dead: not a live point
      break;
    }
    replacement.replace(live, worst, it, rng, run);
  }
  compression.close(live, run);
  compression.finish(settings.live, run);
  return run;
}

}  // namespace admitgen

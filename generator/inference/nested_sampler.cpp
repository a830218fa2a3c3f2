// SPDX-License-Identifier: MIT
#include "inference/nested_sampler.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "inference/ellipsoid_union.hpp"
#include "inference/evidence.hpp"
#include "inference/live_point_clusters.hpp"
#include "inference/slice_step.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace admitgen {
namespace {

constexpr double kMinusInf = -std::numeric_limits<double>::infinity();

/// Running evidence and information (Skilling 2006, eq. 17 for H).
struct EvidenceAccumulator {
  double log_z = kMinusInf;
  double h = 0.0;
  void add(double log_w, double log_l) {
    const double new_log_z = log_add_exp(log_z, log_w);
    const double h_part = std::exp(log_w - new_log_z) * log_l;
    const double h_prev = log_z == kMinusInf ? 0.0 : std::exp(log_z - new_log_z) * (h + log_z);
    h = h_part + h_prev - new_log_z;
    log_z = new_log_z;
  }
};

/// The n live points as columns: position in the unit cube, θ, ln L.
struct LivePoints {
  Eigen::MatrixXd u, theta;
  Eigen::VectorXd log_l;
};

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

/// The constrained step: the dead point is replaced by a uniform draw from the bounding ellipsoids above
/// the contour (NestedSettings::ellipsoid_draws), or by a copy of a random surviving live point (it
/// already satisfies L > L*) moved by slice sampling along its cluster's whitened axes; the new point
/// joins that cluster.
///
/// Which of the two: both give a draw from the constrained prior (the ellipsoids up to how well their union
/// covers the contour), so the choice sets the cost. The ellipsoids serve only while the live points form
/// one cluster: where they split (several modes, or a spare pole trading roles with another across a
/// curved region) a missed corner of the contour would lose posterior mass for good, while a slice chain
/// from a live point reaches wherever live points are. Within one cluster they serve while their
/// likelihood calls per replacement since the last covariance update stay below a slice chain's running
/// mean (counting the draws that missed the contour, and the slice chain after a replacement that found
/// nothing within a slice chain's calls). Draws rejected without a call (outside the cube or the canonical
/// domain of a folded model, which can be most of an ellipsoid that straddles a fold's seam) are counted
/// too, kDrawsPerCall of them as one call. Where the contour is nearly ellipsoidal one or two calls replace
/// 3 + dim slices; where it is far from it, slices serve (docs/method.md, "Sampler and evidence error").
class Replacement {
 public:
  /// Rejected draws (normal deviates, a triangular product, the fold) that cost as much as one likelihood
  /// call: a call at the smallest data sets here (60 points, 3 residues) takes about 20 times a draw at
  /// dim 12; larger data make calls dearer, so this undercounts the calls' share, never the draws'.
  static constexpr long kDrawsPerCall = 20;

  Replacement(const Model& model, const NestedSettings& settings)
      : model_(model),
        n_(settings.live),
        slices_(settings.slices > 0 ? settings.slices : 3 + model.dim()),
        cov_interval_(settings.covariance_interval > 0 ? settings.covariance_interval : std::max(1, n_ / 10)),
        min_cluster_(std::max(2 * model.dim(), 20)),
        ellipsoid_draws_(settings.ellipsoid_draws),
        enlarge_(settings.ellipsoid_enlarge),
        slice_calls_(4.0 * slices_),
        step_(model.dim(), model.prior_transform, model.log_likelihood),
        u_(model.dim()),
        theta_(model.dim()),
        folded_(model.dim()) {}

  void replace(LivePoints& live, Eigen::Index worst, long iteration, Rng& rng, NestedRun& run) {
    // Clusters need enough points for a covariance: at least 2·dim and 20.
    constexpr int kMaxClusters = 8;
    if (iteration % cov_interval_ == 0) {
      clusters_ = cluster_live_points(live.u, min_cluster_, kMaxClusters);
      // Each cluster's slice width starts from the previous update's widths (their geometric mean over
      // clusters: new clusters need not match old ones) and adapts on its own.
      double log_mean = 0.0;
      for (double w : slice_widths_) log_mean += std::log(w);
      const double start = slice_widths_.empty() ? 1.0 : std::exp(log_mean / static_cast<double>(slice_widths_.size()));
      slice_widths_.assign(clusters_.axes.size(), start);
      if (ellipsoid_draws_ && clusters_.axes.size() == 1) {
        bounds_.emplace(live.u, clusters_, enlarge_);
        bound_cost_ = 0.0;
        bound_draws_ = 0;
      } else {
        bounds_.reset();
      }
    }
    int cluster = 0;
    double log_l = 0.0;
    const bool bounded = bounds_ && bound_cost_ <= slice_calls_ * static_cast<double>(bound_draws_ + 1);
    if (!bounded || !draw_from_bounds(live.log_l[worst], rng, run, cluster, log_l)) {
      Eigen::Index start = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n_ - 1)));
      if (start >= worst) ++start;
      cluster = clusters_.label[static_cast<std::size_t>(start)];
      u_ = live.u.col(start);
      theta_ = live.theta.col(start);
      log_l = live.log_l[start];
      step_.set_axes(clusters_.axes[static_cast<std::size_t>(cluster)], slice_widths_[static_cast<std::size_t>(cluster)]);
      const long calls = step_.move(u_, theta_, log_l, live.log_l[worst], slices_, rng);
      run.calls += calls;
      slice_calls_ = 0.9 * slice_calls_ + 0.1 * static_cast<double>(calls);
      if (bounded) bound_cost_ += static_cast<double>(calls);  // the ellipsoids missed: their replacement cost these too
      if (model_.fold) {
        model_.fold(u_.data());
        model_.prior_transform(u_.data(), theta_.data());  // same ln L: the likelihood is invariant
      }
    }
    clusters_.label[static_cast<std::size_t>(worst)] = cluster;
    live.u.col(worst) = u_;
    live.theta.col(worst) = theta_;
    live.log_l[worst] = log_l;
  }

 private:
  /// Draws from the ellipsoids until a point of the canonical domain lies above the contour: true, with
  /// (u_, theta_, log_l) set. A draw outside the unit cube or off the canonical domain (the fold's fixed
  /// points; folding it instead would double the density where an ellipsoid crosses a seam) is rejected
  /// without a likelihood call. Gives up after a slice chain's mean calls or kDrawsPerCall times as many draws.
  bool draw_from_bounds(double log_l_min, Rng& rng, NestedRun& run, int& cluster, double& log_l) {
    const long max_calls = std::max(1L, std::lround(slice_calls_)), max_draws = kDrawsPerCall * max_calls;
    long calls = 0, draws = 0;
    bool found = false;
    for (; draws < max_draws && calls < max_calls && !found; ++draws) {
      if (!bounds_->draw(rng, u_, cluster)) continue;
      if ((u_.array() < 0.0).any() || (u_.array() >= 1.0).any()) continue;
      if (model_.fold) {
        folded_ = u_;
        model_.fold(folded_.data());
        if (folded_ != u_) continue;
      }
      model_.prior_transform(u_.data(), theta_.data());
      log_l = model_.log_likelihood(theta_.data());
      ++calls;
      found = log_l > log_l_min;
    }
    run.calls += calls;
    bound_cost_ += static_cast<double>(calls) + static_cast<double>(draws - calls) / kDrawsPerCall;
    ++bound_draws_;
    return found;
  }

  const Model& model_;
  int n_, slices_, cov_interval_, min_cluster_;
  bool ellipsoid_draws_;
  double enlarge_;
  double slice_calls_;            ///< running mean of a slice chain's likelihood calls
  double bound_cost_ = 0.0;  ///< ellipsoid calls (rejected draws weighted by 1/kDrawsPerCall) since the last update
  long bound_draws_ = 0;     ///< replacements by the ellipsoids since the last update
  SliceStep step_;
  std::vector<double> slice_widths_;  ///< per cluster (inference/slice_step.hpp)
  LivePointClusters clusters_;
  std::optional<EllipsoidUnion> bounds_;
  Eigen::VectorXd u_, theta_, folded_;
};

}  // namespace

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
    const bool converged = status.remaining < settings.dlogz;
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

// SPDX-License-Identifier: MIT
#include "inference/nested_sampler.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "inference/live_point_clusters.hpp"
#include "inference/slice_step.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

double log_add_exp(double a, double b) {
  if (a == -std::numeric_limits<double>::infinity()) return b;
  if (b == -std::numeric_limits<double>::infinity()) return a;
  const double m = std::max(a, b);
  return m + std::log1p(std::exp(-std::abs(a - b)));
}

/// Running evidence and information (Skilling 2006, eq. 17 for H).
struct EvidenceAccumulator {
  double log_z = -std::numeric_limits<double>::infinity();
  double h = 0.0;
  void add(double log_w, double log_l) {
    const double new_log_z = log_add_exp(log_z, log_w);
    const double h_part = std::exp(log_w - new_log_z) * log_l;
    const double h_prev = log_z == -std::numeric_limits<double>::infinity()
                              ? 0.0
                              : std::exp(log_z - new_log_z) * (h + log_z);
    h = h_part + h_prev - new_log_z;
    log_z = new_log_z;
  }
};

}  // namespace

NestedRun run_nested_sampling(int dim, const PriorTransformFn& prior_transform, const LogLikelihoodFn& log_likelihood,
                              const NestedSettings& settings, const NestedProgressFn& progress, const FoldFn& fold) {
  ADMITGEN_ENSURE(dim >= 1, "dimension {}", dim);
  ADMITGEN_ENSURE(settings.live >= 2, "live points {}", settings.live);
  const int n = settings.live;
  const int slices = settings.slices > 0 ? settings.slices : 3 + dim;
  const int cov_interval = settings.covariance_interval > 0 ? settings.covariance_interval : std::max(1, n / 10);
  Rng rng(settings.seed);

  NestedRun run;
  run.dim = dim;
  Eigen::MatrixXd live_u(dim, n), live_theta(dim, n);
  Eigen::VectorXd live_log_l(n);
  // ln L = −∞ marks a point outside the support (e.g. a prior truncated to passive models): the initial
  // live points are drawn by rejection, so the run samples the prior restricted to the support and ln Z is
  // the evidence under that renormalised prior; draws/accepted estimate the support fraction.
  constexpr long kMaxDrawsPerPoint = 10000;
  long draws = 0;
  for (int i = 0; i < n; ++i) {
    do {
      if (draws >= kMaxDrawsPerPoint * n)
        throw InputError(fmt::format("fewer than 1 in {} prior draws has a finite likelihood (a support this small, "
                                     "e.g. a prior truncated to passive models when almost none of them is, "
                                     "cannot be sampled)", kMaxDrawsPerPoint));
      for (int k = 0; k < dim; ++k) live_u(k, i) = rng.uniform();
      if (fold) fold(live_u.col(i).data());
      prior_transform(live_u.col(i).data(), live_theta.col(i).data());
      live_log_l[i] = log_likelihood(live_theta.col(i).data());
      ++run.calls;
      ++draws;
    } while (live_log_l[i] == -std::numeric_limits<double>::infinity());
  }
  run.log_support_fraction = std::log(static_cast<double>(n) / static_cast<double>(draws));

  SliceStep step(dim, prior_transform, log_likelihood);
  // Clusters need enough points for a covariance: at least 2·dim and 20.
  constexpr int kMaxClusters = 8;
  const int min_cluster = std::max(2 * dim, 20);
  LivePointClusters clusters;
  EvidenceAccumulator acc;
  const double log_shrink = -1.0 / n;                         // ln(X_i / X_{i−1})
  const double log_width_factor = std::log(-std::expm1(log_shrink));  // ln(1 − e^{−1/n})
  double log_x = 0.0;                                         // ln X_{i−1}
  Eigen::VectorXd u(dim), theta(dim);
  run.stopped_by = "max_iterations";
  for (long it = 0; it < settings.max_iterations; ++it) {
    Eigen::Index worst = 0;
    const double log_l_min = live_log_l.minCoeff(&worst);
    const double log_w = log_l_min + log_x + log_width_factor;  // L_i (X_{i−1} − X_i)
    acc.add(log_w, log_l_min);
    run.samples.insert(run.samples.end(), live_theta.col(worst).data(), live_theta.col(worst).data() + dim);
    run.log_likelihood.push_back(log_l_min);
    run.log_weight.push_back(log_w);
    log_x += log_shrink;
    run.iterations = it + 1;

    const double remaining = log_add_exp(acc.log_z, live_log_l.maxCoeff() + log_x) - acc.log_z;
    if (progress && it % 500 == 0) progress(NestedStatus{it, acc.log_z, remaining, run.calls});
    if (remaining < settings.dlogz) {
      run.stopped_by = "dlogz";
      live_log_l[worst] = -std::numeric_limits<double>::infinity();  // already dead: not a live point
      break;
    }

    if (it % cov_interval == 0) clusters = cluster_live_points(live_u, min_cluster, kMaxClusters);
    // Start from a copy of a random surviving live point (it already satisfies L > L*) and move it
    // with the axes of its cluster; the new point joins that cluster.
    Eigen::Index start = static_cast<Eigen::Index>(rng.below(static_cast<std::uint64_t>(n - 1)));
    if (start >= worst) ++start;
    const int cluster = clusters.label[static_cast<std::size_t>(start)];
    u = live_u.col(start);
    theta = live_theta.col(start);
    double log_l = live_log_l[start];
    step.set_axes(clusters.axes[static_cast<std::size_t>(cluster)]);
    run.calls += step.move(u, theta, log_l, log_l_min, slices, rng);
    if (fold) {
      fold(u.data());
      prior_transform(u.data(), theta.data());  // same ln L: the likelihood is invariant
    }
    clusters.label[static_cast<std::size_t>(worst)] = cluster;
    live_u.col(worst) = u;
    live_theta.col(worst) = theta;
    live_log_l[worst] = log_l;
  }

  // The remaining live points share the last volume X equally (Skilling 2006, §5).
  std::vector<Eigen::Index> order;
  for (Eigen::Index i = 0; i < n; ++i)
    if (std::isfinite(live_log_l[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return live_log_l[a] < live_log_l[b]; });
  const double log_share = log_x - std::log(static_cast<double>(order.size()));
  for (Eigen::Index i : order) {
    const double log_w = live_log_l[i] + log_share;
    acc.add(log_w, live_log_l[i]);
    run.samples.insert(run.samples.end(), live_theta.col(i).data(), live_theta.col(i).data() + dim);
    run.log_likelihood.push_back(live_log_l[i]);
    run.log_weight.push_back(log_w);
  }
  run.log_z = acc.log_z;
  run.information = std::max(acc.h, 0.0);
  run.log_z_error = std::sqrt(run.information / n);
  run.max_log_likelihood = *std::max_element(run.log_likelihood.begin(), run.log_likelihood.end());
  return run;
}

}  // namespace admitgen

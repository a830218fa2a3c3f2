// SPDX-License-Identifier: MIT
#include "inference/posterior.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace admitgen {

Eigen::ArrayXd posterior_weights(const NestedRun& run) {
  Eigen::ArrayXd w(static_cast<Eigen::Index>(run.size()));
  for (std::size_t i = 0; i < run.size(); ++i) w[static_cast<Eigen::Index>(i)] = std::exp(run.log_weight[i] - run.log_z);
  return w / w.sum();
}

double effective_sample_size(const Eigen::ArrayXd& weights) {
  return weights.sum() * weights.sum() / weights.square().sum();
}

double weighted_quantile(const Eigen::ArrayXd& values, const Eigen::ArrayXd& weights, double q) {
  ADMITGEN_ENSURE(values.size() == weights.size() && values.size() > 0, "sizes {} {}", values.size(), weights.size());
  std::vector<Eigen::Index> idx(static_cast<std::size_t>(values.size()));
  std::iota(idx.begin(), idx.end(), Eigen::Index{0});
  std::stable_sort(idx.begin(), idx.end(), [&](auto a, auto b) { return values[a] < values[b]; });
  const double total = weights.sum();
  double cumulative = 0.0, prev_mid = 0.0, prev_value = values[idx.front()];
  bool first = true;
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const double w = weights[idx[k]] / total;
    if (w == 0.0 && k + 1 < idx.size()) continue;  // a zero-weight point stands for no posterior mass
    const double mid = cumulative + 0.5 * w;  // the cumulative weight this value stands for
    if (mid >= q) {
      if (first || mid == prev_mid) return values[idx[k]];
      const double t = (q - prev_mid) / (mid - prev_mid);
      return prev_value + t * (values[idx[k]] - prev_value);
    }
    first = false;
    cumulative += w;
    prev_mid = mid;
    prev_value = values[idx[k]];
  }
  return values[idx.back()];
}

std::size_t max_likelihood_index(const NestedRun& run) {
  return static_cast<std::size_t>(std::max_element(run.log_likelihood.begin(), run.log_likelihood.end()) -
                                  run.log_likelihood.begin());
}

std::vector<ParameterSummary> summarize(const NestedRun& run, const std::vector<std::string>& names) {
  ADMITGEN_ENSURE(static_cast<int>(names.size()) == run.dim, "{} names for {} parameters", names.size(), run.dim);
  const Eigen::ArrayXd w = posterior_weights(run);
  const std::size_t best = max_likelihood_index(run);
  std::vector<ParameterSummary> out;
  for (int k = 0; k < run.dim; ++k) {
    Eigen::ArrayXd v(w.size());
    for (Eigen::Index i = 0; i < w.size(); ++i) v[i] = run.point(static_cast<std::size_t>(i))[k];
    const double mean = (w * v).sum();
    const double var = (w * (v - mean).square()).sum();
    out.push_back({names[static_cast<std::size_t>(k)], mean, std::sqrt(std::max(var, 0.0)), weighted_quantile(v, w, 0.025),
                   weighted_quantile(v, w, 0.975), run.point(best)[k]});
  }
  return out;
}

std::vector<std::size_t> resample_indices(const Eigen::ArrayXd& weights, std::size_t count, Rng& rng) {
  std::vector<std::size_t> idx;
  idx.reserve(count);
  const double total = weights.sum();
  const double offset = rng.uniform();
  double cumulative = weights[0] / total;
  std::size_t i = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double target = (static_cast<double>(k) + offset) / static_cast<double>(count);
    while ((cumulative < target || weights[static_cast<Eigen::Index>(i)] == 0.0) &&
           i + 1 < static_cast<std::size_t>(weights.size()))
      cumulative += weights[static_cast<Eigen::Index>(++i)] / total;
    std::size_t pick = i;  // rounding can run onto trailing zero-weight points: step back off them
    while (weights[static_cast<Eigen::Index>(pick)] == 0.0 && pick > 0) --pick;
    idx.push_back(pick);
  }
  return idx;
}

}  // namespace admitgen

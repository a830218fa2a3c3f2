// SPDX-License-Identifier: MIT
#include "inference/run_merge.hpp"

#include "core/errors.hpp"
#include "inference/evidence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

constexpr double kMinusInf = -std::numeric_limits<double>::infinity();

/// One weighted point of a part: where it sits, what orders it, and the part's live count at its death.
struct Point {
  std::size_t part, index;
  double key;
  int live;
};

/// The likelihood that orders a part's points: the one its run sampled.
const std::vector<double>& sampled(const NestedRun& run) {
  return run.sampled_log_likelihood.empty() ? run.log_likelihood : run.sampled_log_likelihood;
}

}  // namespace

NestedRun merge_runs(const std::vector<RunPart>& parts) {
  ADMITGEN_ENSURE(!parts.empty(), "no run to merge");
  const bool marginal = !parts.front().run->sampled_log_likelihood.empty();
  NestedRun merged;
  merged.dim = parts.front().run->dim;
  merged.stopped_by = parts.front().run->stopped_by;
  std::vector<Point> points;
  std::vector<std::pair<std::size_t, std::size_t>> unweighted;
  int live_sum = 0;
  double support = 0.0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const NestedRun& run = *parts[k].run;
    const int n = parts[k].live;
    ADMITGEN_ENSURE(run.dim == merged.dim && n >= 1 && marginal == !run.sampled_log_likelihood.empty(),
                    "runs of different shapes cannot be merged");
    const std::vector<double>& key = sampled(run);
    const std::size_t deaths = static_cast<std::size_t>(run.iterations);
    int closing = 0;  // final live points of this part seen so far
    for (std::size_t i = 0; i < run.size(); ++i) {
      if (run.log_weight[i] == kMinusInf) {
        unweighted.emplace_back(k, i);
        continue;
      }
      points.push_back({k, i, key[i], i < deaths ? n : n - closing++});
    }
    live_sum += n;
    support += n * std::exp(run.log_support_fraction);
    merged.calls += run.calls;
    merged.iterations += run.iterations;
  }
  std::stable_sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return a.key < b.key || (a.key == b.key && (a.part < b.part || (a.part == b.part && a.index < b.index)));
  });
  // Each part's live count at its next point; the merged count at a point is their sum there (a part with no
  // point left has no thread alive). after[i]: the next point of point i's part.
  std::vector<std::size_t> after(points.size(), points.size()), first(parts.size(), points.size());
  for (std::size_t i = points.size(); i-- > 0;) {
    after[i] = first[points[i].part];
    first[points[i].part] = i;
  }
  std::vector<int> next_live(parts.size(), 0);
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (first[k] < points.size()) next_live[k] = points[first[k]].live;
  EvidenceAccumulator acc;
  double log_x = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    int n = 0;
    for (int c : next_live) n += c;
    const double shrink = -1.0 / n;  // E[ln t] for the largest of n uniform draws
    const double log_w = p.key + log_x + std::log(-std::expm1(shrink));
    acc.add(log_w, p.key);
    log_x += shrink;
    const NestedRun& run = *parts[p.part].run;
    merged.samples.insert(merged.samples.end(), run.point(p.index), run.point(p.index) + run.dim);
    merged.log_likelihood.push_back(run.log_likelihood[p.index]);
    if (marginal) merged.sampled_log_likelihood.push_back(p.key);
    merged.log_weight.push_back(log_w);
    next_live[p.part] = after[i] < points.size() ? points[after[i]].live : 0;
  }
  for (const auto& [k, i] : unweighted) {
    const NestedRun& run = *parts[k].run;
    merged.samples.insert(merged.samples.end(), run.point(i), run.point(i) + run.dim);
    merged.log_likelihood.push_back(run.log_likelihood[i]);
    if (marginal) merged.sampled_log_likelihood.push_back(run.sampled_log_likelihood[i]);
    merged.log_weight.push_back(kMinusInf);
  }
  merged.log_z = acc.log_z;
  merged.information = std::max(acc.h, 0.0);
  merged.log_z_error = std::sqrt(merged.information / live_sum);
  merged.max_log_likelihood = *std::max_element(merged.log_likelihood.begin(), merged.log_likelihood.end());
  merged.log_support_fraction = std::log(support / live_sum);
  return merged;
}

// c in Var(ln Z_k) = c / n_k, estimated from the parts' scatter about their live-weighted mean μ:
// E[Σ n_k (ln Z_k − μ)²] = Σ n_k (c/n_k − c/N) = c (m − 1) for m parts of N live points in all, so the sum over
// m − 1 is unbiased for c, and c / N for the variance of the merged ln Z.
double scatter_error(const std::vector<RunPart>& parts) {
  if (parts.size() < 2) return 0.0;
  double live = 0.0, mean = 0.0;
  for (const RunPart& p : parts) {
    live += p.live;
    mean += p.live * p.run->log_z;
  }
  mean /= live;
  double sum = 0.0;
  for (const RunPart& p : parts) sum += p.live * (p.run->log_z - mean) * (p.run->log_z - mean);
  return std::sqrt(sum / static_cast<double>(parts.size() - 1) / live);
}

}  // namespace admitgen

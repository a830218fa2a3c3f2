// SPDX-License-Identifier: MIT
#include "inference/merged_runs.hpp"

#include "core/errors.hpp"
#include "inference/evidence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace admitgen {
namespace {

struct Row {
  std::size_t run, index;
};

/// Appends `rows` to `out` in ascending ln L (ties by run, then by index: deterministic).
void append_sorted(std::vector<Row> rows, const std::vector<NestedRun>& runs, double log_k, NestedRun& out) {
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    return runs[a.run].log_likelihood[a.index] < runs[b.run].log_likelihood[b.index];
  });
  for (const Row& r : rows) {
    const NestedRun& run = runs[r.run];
    out.samples.insert(out.samples.end(), run.point(r.index), run.point(r.index) + run.dim);
    out.log_likelihood.push_back(run.log_likelihood[r.index]);
    out.log_weight.push_back(run.log_weight[r.index] - log_k);
  }
}

}  // namespace

NestedRun merge_runs(const std::vector<NestedRun>& runs, int live) {
  ADMITGEN_ENSURE(!runs.empty() && live >= 1, "{} runs of {} live points", runs.size(), live);
  if (runs.size() == 1) return runs.front();
  const double k = static_cast<double>(runs.size()), log_k = std::log(k);
  NestedRun out;
  out.dim = runs.front().dim;
  std::vector<Row> body, ends;
  double log_sum_z = -std::numeric_limits<double>::infinity(), support = 0.0;
  for (std::size_t j = 0; j < runs.size(); ++j) {
    const NestedRun& run = runs[j];
    ADMITGEN_ENSURE(run.dim == out.dim, "runs of {} and {} dimensions", run.dim, out.dim);
    const std::size_t first_end = run.size() - std::min(run.size(), static_cast<std::size_t>(live));
    for (std::size_t i = 0; i < run.size(); ++i) (i < first_end ? body : ends).push_back({j, i});
    log_sum_z = log_add_exp(log_sum_z, run.log_z);
    support += std::exp(run.log_support_fraction);
    out.calls += run.calls;
    out.iterations += run.iterations;
    if (run.stopped_by != "dlogz" || out.stopped_by.empty()) out.stopped_by = run.stopped_by;
  }
  append_sorted(std::move(body), runs, log_k, out);
  append_sorted(std::move(ends), runs, log_k, out);
  out.log_z = log_sum_z - log_k;
  double variance = 0.0;
  for (const NestedRun& run : runs) variance += std::pow(std::exp(run.log_z - log_sum_z) * run.log_z_error, 2);
  out.log_z_error = std::sqrt(variance);
  // H = Σ p_i ln(L_i / Z) over the merged posterior.
  double information = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double p = std::exp(out.log_weight[i] - out.log_z);
    if (p > 0.0) information += p * (out.log_likelihood[i] - out.log_z);
  }
  out.information = std::max(information, 0.0);
  out.max_log_likelihood = *std::max_element(out.log_likelihood.begin(), out.log_likelihood.end());
  out.log_support_fraction = std::log(support / k);
  return out;
}

}  // namespace admitgen

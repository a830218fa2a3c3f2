// SPDX-License-Identifier: MIT
/// @file
/// The driver that compares models by their evidence: `fit` over model orders (selection/fit.hpp), `diagnose`
/// over candidate effects (diagnosis/effect_identification.hpp). It runs one job per model on a pool of threads
/// (core/parallel.hpp), derives each job's seed from its own stream, shows the running jobs and the time left on
/// stderr (core/progress.hpp) and times the jobs. What a job computes, and what is made of the results, are the
/// caller's policies: a fit's missed-mode re-runs, grid growth and selection rule; a diagnosis's early stop,
/// screening and decisive rule.
#pragma once

#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "inference/nested_sampler.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace admitgen {

/// One model of a comparison as the status line shows it.
struct ComparisonJob {
  std::string label;  ///< its name on the status line
  double work = 1.0;  ///< expected work, in a unit shared by the jobs of one run (for the time left)
  /// Its run's stop (NestedSettings::dlogz): the run's progress is how far the logarithm of its
  /// remaining-evidence estimate has come down from its first value towards it.
  double dlogz = 0.01;
};

class Comparison {
 public:
  /// `what` names the jobs on the status line ("orders", "candidates", "units").
  Comparison(Progress& progress, int threads, std::string what);

  /// The seed of a job on stream `stream` of a comparison seeded with `seed`. Each job draws from its own
  /// stream, so the results depend on neither the thread count nor which worker ran what.
  static std::uint64_t job_seed(std::uint64_t seed, std::uint64_t stream);

  /// body(k, status): computes job k; status(s) reports its nested-sampling run's progress.
  using Body = std::function<void(std::size_t job, const NestedProgressFn& status)>;
  /// A permanent line printed above the status line when job k is done, given its time (empty: none).
  using DoneLine = std::function<std::string(std::size_t job, const TaskTime& time)>;

  /// Runs body(k, ·) for every k of `queue` (started in that order: largest first is best) on the pool and
  /// returns each job's time, indexed like `jobs` (zero for a job not queued). Every job runs even if another
  /// throws; the first exception is rethrown after the status line is cleared.
  std::vector<TaskTime> run(const std::vector<ComparisonJob>& jobs, const std::vector<std::size_t>& queue,
                            const Body& body, const DoneLine& done_line = {});

 private:
  Progress& progress_;
  int threads_;
  std::string what_;
};

}  // namespace admitgen

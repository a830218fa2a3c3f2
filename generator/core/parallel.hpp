// SPDX-License-Identifier: MIT
/// @file
/// A pool of worker threads over independent tasks (orders in `fit`, candidate effects in `diagnose`).
/// Each task writes only its own result slot and draws from its own seed stream, so results do not
/// depend on the number of threads or on which worker ran what; only the order in which tasks start
/// (the given queue: largest first is best) is fixed.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace admitgen {

/// The worker count for a requested `threads` (0 = all cores), at most `tasks` and at least 1.
std::size_t worker_count(int threads, std::size_t tasks);

/// Runs task(queue[k]) for every k on worker_count(threads, queue.size()) threads (the calling thread is
/// one of them). Every task runs even if another throws; the first exception (in time) is rethrown.
void run_in_parallel(const std::vector<std::size_t>& queue, int threads, const std::function<void(std::size_t)>& task);

/// CPU time of the calling thread in seconds (POSIX CLOCK_THREAD_CPUTIME_ID; 0 where unavailable): what a task
/// on the pool cost, for benchmarks on a shared machine (never stored in an output).
double thread_cpu_seconds();

/// Wall and thread CPU time of one task.
struct TaskTime {
  double seconds = 0.0;
  double cpu_seconds = 0.0;
};

/// Runs task() on the calling thread and returns how long it took.
TaskTime timed(const std::function<void()>& task);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "inference/comparison.hpp"

#include "core/rng.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>

namespace admitgen {
namespace {

/// The status line: jobs done of those queued, the time left (elapsed time scaled by the work not yet done;
/// shown once 5 % is done), and each running job with its progress.
class ComparisonStatus {
 public:
  ComparisonStatus(Progress& out, const std::vector<ComparisonJob>& jobs, const std::vector<std::size_t>& queue,
                   std::string what)
      : out_(out), jobs_(jobs), what_(std::move(what)), queued_(queue.size()),
        start_(std::chrono::steady_clock::now()) {
    for (std::size_t k : queue) total_ += jobs[k].work;
  }

  void running(std::size_t k, const NestedStatus& s) {
    if (!out_.enabled()) return;
    std::lock_guard<std::mutex> lock(mutex_);
    Active& a = active_[k];
    if (!a.started) a.started = true, a.first = s.remaining;
    const double dlogz = jobs_[k].dlogz;
    a.fraction = a.first > dlogz && s.remaining > 0.0
                     ? std::clamp(std::log(a.first / s.remaining) / std::log(a.first / dlogz), 0.0, 0.99)
                     : 0.0;
    show();
  }

  void done(std::size_t k, const std::string& line) {
    std::lock_guard<std::mutex> lock(mutex_);
    active_.erase(k);
    finished_ += jobs_[k].work;
    ++count_;
    if (!line.empty()) out_.message(line);
    show();
  }

 private:
  struct Active {
    bool started = false;
    double first = 0.0, fraction = 0.0;
  };
  void show() {
    if (!out_.enabled()) return;
    double work = finished_;
    std::string running;
    for (const auto& [k, a] : active_) {
      work += jobs_[k].work * a.fraction;
      running += fmt::format("  {} {:.0f} %", jobs_[k].label, 100.0 * a.fraction);
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double fraction = total_ > 0.0 ? work / total_ : 0.0;
    const std::string left =
        fraction > 0.05 ? fmt::format(", about {:.0f} s left", elapsed * (1.0 - fraction) / fraction) : "";
    out_.update(fmt::format("[{} of {} {} done{}]{}", count_, queued_, what_, left, running));
  }
  Progress& out_;
  const std::vector<ComparisonJob>& jobs_;
  std::string what_;
  std::size_t queued_, count_ = 0;
  double total_ = 0.0, finished_ = 0.0;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::map<std::size_t, Active> active_;
};

}  // namespace

Comparison::Comparison(Progress& progress, int threads, std::string what)
    : progress_(progress), threads_(threads), what_(std::move(what)) {}

std::uint64_t Comparison::job_seed(std::uint64_t seed, std::uint64_t stream) { return derive_seed(seed, stream); }

std::vector<TaskTime> Comparison::run(const std::vector<ComparisonJob>& jobs, const std::vector<std::size_t>& queue,
                                      const Body& body, const DoneLine& done_line) {
  std::vector<TaskTime> times(jobs.size());
  ComparisonStatus status(progress_, jobs, queue, what_);
  try {
    run_in_parallel(queue, threads_, [&](std::size_t k) {
      times[k] = timed([&] { body(k, [&](const NestedStatus& s) { status.running(k, s); }); });
      status.done(k, done_line ? done_line(k, times[k]) : std::string());
    });
  } catch (...) {
    progress_.finish();
    throw;
  }
  progress_.finish();
  return times;
}

}  // namespace admitgen

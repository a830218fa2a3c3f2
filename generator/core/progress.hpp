// SPDX-License-Identifier: MIT
/// @file
/// Progress on stderr for long work: a single self-overwriting status line when stderr is a
/// terminal, nothing otherwise (or with --quiet). Thread-safe; throttled to a few updates a second.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace admitgen {

class Progress {
 public:
  /// Enabled only if `wanted` and stderr is a terminal.
  explicit Progress(bool wanted);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool enabled() const { return enabled_; }
  /// Replaces the status line (throttled unless `force`).
  void update(const std::string& line, bool force = false);
  /// Prints a permanent line above the status line.
  void message(const std::string& line);
  /// Clears the status line.
  void finish();

 private:
  bool enabled_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_{};
  std::size_t shown_ = 0;
};

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "core/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace admitgen {

Progress::Progress(bool wanted) : enabled_(wanted && ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::update(const std::string& line, bool force) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (!force && now - last_ < std::chrono::milliseconds(150)) return;
  last_ = now;
  std::string padded = line;
  if (padded.size() < shown_) padded.append(shown_ - padded.size(), ' ');
  std::fprintf(stderr, "\r%s", padded.c_str());
  std::fflush(stderr);
  shown_ = line.size();
}

void Progress::message(const std::string& line) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "\r%s%s\n", line.c_str(),
               line.size() < shown_ ? std::string(shown_ - line.size(), ' ').c_str() : "");
  shown_ = 0;
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (shown_ > 0) std::fprintf(stderr, "\r%s\r", std::string(shown_, ' ').c_str());
  std::fflush(stderr);
  shown_ = 0;
}

}  // namespace admitgen

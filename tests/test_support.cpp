// SPDX-License-Identifier: MIT
#include "test_support.hpp"

#include <array>
#include <cmath>
#include <numeric>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <sys/wait.h>

namespace admitgen::test {

CommandResult run_admitgen(const std::string& args) {
  const std::string cmd = std::string("'") + ADMITGEN_EXE + "' " + args + " 2>&1";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("popen failed: " + cmd);
  std::string out;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

std::string scratch_dir(const std::string& name) {
  const auto dir = std::filesystem::current_path() / "scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string sample(const std::string& relative) { return std::string(ADMITGEN_SAMPLES) + "/" + relative; }

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

SeedScatter seed_scatter(const std::vector<double>& log_z, const std::vector<double>& log_z_error) {
  const double n = static_cast<double>(log_z.size());
  SeedScatter s;
  s.mean = std::accumulate(log_z.begin(), log_z.end(), 0.0) / n;
  double var = 0.0;
  for (double v : log_z) var += (v - s.mean) * (v - s.mean);
  s.spread = std::sqrt(var / (n - 1.0));
  s.reported = std::accumulate(log_z_error.begin(), log_z_error.end(), 0.0) / n;
  return s;
}

Eigen::MatrixXd random_matrix(Rng& rng, Eigen::Index r, Eigen::Index c) {
  Eigen::MatrixXd m(r, c);
  for (Eigen::Index i = 0; i < r; ++i)
    for (Eigen::Index j = 0; j < c; ++j) m(i, j) = 2.0 * rng.uniform() - 1.0;
  return m;
}

}  // namespace admitgen::test

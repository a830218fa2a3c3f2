// SPDX-License-Identifier: MIT
/// @file
/// What the pole search of the passive estimate gains, on a fit directory (a program, not a test;
/// docs/passivity.md, "Searching the poles"). For each order's posterior draws (posterior_QxSy.csv, as `fit`
/// writes them) it takes the 16 draws of highest likelihood as the candidates and prints, per order: the best
/// draw's relative RMS residual, the passive estimate's with the sampled poles only and with the pole search,
/// the ratio to the best draw, and the CPU seconds each took (one thread; CPU time, so that other work on the
/// machine does not count).
/// Usage: bench_passive_estimate FIT_DIR DATA.csv [COLUMNS] [STARTS]
/// (the posterior's draws are equal-weight resamples, so their best is close to, not the same as, the run's).
#include "data/csv_reader.hpp"
#include "inference/likelihood.hpp"
#include "passivity/passive_estimate.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace admitgen;
namespace {

/// CPU seconds of this process since `t` (std::clock).
double seconds_since(std::clock_t t) { return double(std::clock() - t) / CLOCKS_PER_SEC; }

/// The rows of a posterior CSV (header skipped), each a θ packed as model/order.hpp.
std::vector<Eigen::VectorXd> read_draws(const std::string& path, const Order& order) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<Eigen::VectorXd> out;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    Eigen::VectorXd th(order.dim());
    std::string cell;
    for (int i = 0; i < order.dim() && std::getline(row, cell, ','); ++i) th[i] = std::stod(cell);
    out.push_back(th);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    fmt::print(stderr, "usage: bench_passive_estimate FIT_DIR DATA.csv [COLUMNS] [STARTS]\n");
    return 2;
  }
  ReadOptions read;
  if (argc > 3) read.columns = ColumnMap::parse(argv[3]);
  const int starts = argc > 4 ? std::stoi(argv[4]) : passivity::PassiveEstimate::kStarts;
  const Measurement data = read_measurement(argv[2], read);
  std::vector<std::string> files;
  for (const auto& f : std::filesystem::directory_iterator(argv[1])) {
    const std::string name = f.path().filename().string();
    if (name.rfind("posterior_Q", 0) == 0 && f.path().extension() == ".csv") files.push_back(f.path().string());
  }
  std::sort(files.begin(), files.end());
  fmt::print("{:6} {:>10} {:>10} {:>10} {:>7} {:>8} {:>8}  {}\n", "order", "best draw", "sampled", "searched", "ratio",
             "t_sampled", "t_search", "certified");
  double total_sampled = 0.0, total_search = 0.0;
  for (const auto& path : files) {
    const std::string stem = std::filesystem::path(path).stem().string();
    const Order order = Order::parse(stem.substr(std::string("posterior_").size()));
    std::vector<Eigen::VectorXd> draws = read_draws(path, order);
    const Likelihood likelihood(data, order, DataCount::two_per_point);
    std::vector<std::pair<double, std::size_t>> ranked;
    for (std::size_t i = 0; i < draws.size(); ++i) ranked.emplace_back(-likelihood(draws[i].data()), i);
    std::sort(ranked.begin(), ranked.end());
    std::vector<Eigen::VectorXd> candidates;
    for (std::size_t k = 0; k < std::min<std::size_t>(16, ranked.size()); ++k) candidates.push_back(draws[ranked[k].second]);
    std::clock_t t = std::clock();
    const auto sampled = passivity::passive_estimate(data, order, candidates, DataCount::two_per_point, 0);
    const double t_sampled = seconds_since(t);
    t = std::clock();
    const auto searched = passivity::passive_estimate(data, order, candidates, DataCount::two_per_point, starts);
    const double t_search = seconds_since(t);
    total_sampled += t_sampled;
    total_search += t_search;
    fmt::print("{:6} {:10.5f} {:10.5f} {:10.5f} {:7.3f} {:8.3f} {:8.3f}  {}{}\n", order.name(),
               searched.best_sample_relative_rms_residual, sampled.relative_rms_residual,
               searched.relative_rms_residual,
               searched.relative_rms_residual / searched.best_sample_relative_rms_residual, t_sampled, t_search,
               searched.certified ? "yes" : "NO", searched.poles_searched ? " (poles searched)" : "");
  }
  fmt::print("total seconds: sampled poles {:.3f}, with the search {:.3f}\n", total_sampled, total_search);
  return 0;
}

// SPDX-License-Identifier: MIT
/// @file
/// Fit benchmark (a program, not a test): prints
///  1. likelihood evaluations per second and ns per (frequency point × pole term) for several orders,
///     with a plain std::complex loop over the same model as the baseline ratio;
///  2. for each order of the Q0-3 × S0-3 grid on the reference file: likelihood calls, wall seconds,
///     ln Z ± error;
///  3. the whole grid's wall time with 1 and 2 threads;
///  2-3 for each sampler in turn (full, then poles), plus Q1S1 alone, so the two print side by side.
///  4. with --basotect: the README's quick start (samples/basotect_tuberlin/round_10cm.csv, columns
///     f,_,_,_,_,re,im,_, 100 live points, 2 threads), each sampler in turn.
///  5. with --order QxSy (and optionally --live N, --sampler full|poles, --basotect for the quick-start
///     file): that order alone, no other section: calls, seconds, ns per call, the sampler used and
///     any fallback (for profiling one order).
///  5-6 take --slices K (slices per replacement; default 3 + dim), --dlogz X (default automatic) and --runs R
///  (independent runs per order, merged; default FitSettings::runs).
///  6. with --order QxSy --seeds N: that order on seeds S … S + N − 1 (two at a time), then the spread of ln Z
///     over the seeds against the mean reported error, and the mean calls: what a change of the sampler must be
///     judged by (one seed's calls and ln Z scatter more than most changes move them; docs/validation.md, "Speed").
/// Usage: bench_fit [DATA.csv] [--quick] [--basotect] [--order QxSy [--live N] [--sampler KIND] [--seed S]
///  [--seeds N] [--slices K] [--dlogz X] [--runs R]]  (--quick skips the 1-thread grid)
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "data/csv_reader.hpp"
#include "inference/likelihood.hpp"
#include "inference/pole_space.hpp"
#include "inference/residue_gram.hpp"
#include "inference/residue_evidence.hpp"
#include "inference/priors.hpp"
#include "selection/fit.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <complex>
#include <cstring>
#include <string>
#include <vector>

using namespace admitgen;
using Clock = std::chrono::steady_clock;

namespace {

/// Baseline: the model written term by term with std::complex, no vectorisation.
double naive_sum_squares(const Order& o, const double* th, const Measurement& m) {
  double e = 0.0;
  for (Eigen::Index i = 0; i < m.size(); ++i) {
    const std::complex<double> jw(0.0, 2.0 * EIGEN_PI * m.f_hz[i]);
    std::complex<double> g = th[0];
    for (int q = 0; q < o.q(); ++q) g += th[Order::a(q)] / (th[Order::lambda(q)] + jw);
    for (int s = 0; s < o.s(); ++s) {
      const std::complex<double> big(th[o.b(s)], th[o.c(s)]), pole(th[o.alpha(s)], th[o.beta(s)]);
      g += big / (pole + jw) + std::conj(big) / (std::conj(pole) + jw);
    }
    e += std::norm(m.y[i] - g);
  }
  return e;
}

void likelihood_throughput(const Measurement& data) {
  fmt::print("## Likelihood throughput ({} points)\n", data.size());
  fmt::print("{:<6} {:>6} {:>14} {:>12} {:>16} {:>14} {:>16}\n", "order", "terms", "calls/s", "ns/call", "ns/(point*term)",
             "vs std::complex", "marginal ns/call");
  Rng rng(7);
  for (const Order o : {Order(0, 1), Order(1, 1), Order(2, 2), Order(3, 3)}) {
    const PriorTransform t(o, PriorRanges::table1(), true);
    const Likelihood like(data, o, DataCount::two_per_point);
    constexpr int kSets = 64;
    std::vector<double> thetas(static_cast<std::size_t>(kSets * o.dim())), u(static_cast<std::size_t>(o.dim()));
    for (int k = 0; k < kSets; ++k) {
      for (auto& x : u) x = rng.uniform();
      t(u.data(), thetas.data() + k * o.dim());
    }
    const int terms = o.q() + 2 * o.s();
    const long reps = 200000 / (1 + terms);
    double sink = 0.0;
    auto t0 = Clock::now();
    for (long r = 0; r < reps; ++r) sink += like(thetas.data() + (r % kSets) * o.dim());
    const double fast = std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(reps);
    t0 = Clock::now();
    for (long r = 0; r < reps / 4; ++r) sink += naive_sum_squares(o, thetas.data() + (r % kSets) * o.dim(), data);
    const double naive = std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(reps / 4);
    // The closed-form marginal of the pole sampler at the same poles (residues and noise integrated out).
    const ResidueEvidence marginal(data, o, DataCount::two_per_point, kDefaultAdmittanceScale);
    const auto poles_of = pole_indices(o);
    std::vector<double> poles(static_cast<std::size_t>(kSets) * poles_of.size() + 1);
    for (int k = 0; k < kSets; ++k)
      for (std::size_t j = 0; j < poles_of.size(); ++j)
        poles[static_cast<std::size_t>(k) * poles_of.size() + j] = thetas[static_cast<std::size_t>(k * o.dim() + poles_of[j])];
    t0 = Clock::now();
    for (long r = 0; r < reps; ++r) sink += marginal(poles.data() + static_cast<std::size_t>(r % kSets) * poles_of.size());
    const double marg = std::chrono::duration<double>(Clock::now() - t0).count() / static_cast<double>(reps);
    fmt::print("{:<6} {:>6} {:>14.3g} {:>12.1f} {:>16.3f} {:>13.2f}x {:>16.1f}{}\n", o.name(), terms, 1.0 / fast, fast * 1e9,
               fast * 1e9 / (static_cast<double>(data.size()) * terms), naive / fast, marg * 1e9, sink == 0.123 ? "!" : "");
  }
}

double grid(const Measurement& data, int threads, bool print_models, SamplerKind kind = SamplerKind::full,
            int qmax = 3, int smax = 3, int live = 500) {
  FitSettings s;
  s.sampler.live = live;
  s.threads = threads;
  s.sampler_kind = kind;
  s.qmax = qmax;
  s.smax = smax;
  Progress quiet(false);
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  const FitResult fit = run_fit(data, s, quiet);
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  fmt::print("(process CPU {:.1f} s over {:.1f} s wall, all threads, re-runs included)\n",
             static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC, wall);
  if (print_models) {
    fmt::print("{:<6} {:>10} {:>12} {:>7} {:>9} {:>9} {:>10} {:>11} {:>6}  {}\n", "order", "calls", "ln Z", "± err", "wall s",
               "CPU s", "calls/iter", "CPU ns/call", "used", "fallback");
    long total = 0;
    double cpu = 0.0;
    for (const auto& m : fit.models) {
      total += m.run.calls;
      cpu += m.cpu_seconds;
      fmt::print("{:<6} {:>10} {:>12.2f} {:>7.2f} {:>9.2f} {:>9.2f} {:>10.1f} {:>11.0f} {:>6}  {}\n", m.order.name(),
                 m.run.calls, m.run.log_z, m.run.log_z_error, m.seconds, m.cpu_seconds,
                 static_cast<double>(m.run.calls) / std::max(1.0, static_cast<double>(m.run.iterations)),
                 m.cpu_seconds * 1e9 / static_cast<double>(m.run.calls), m.sampler == "full" ? "full" : "poles",
                 m.sampler_note);
    }
    fmt::print("total likelihood calls: {}, CPU {:.1f} s (summed over orders, re-runs for missed modes excluded)\n",
               total, cpu);
    for (const auto& w : fit.warnings) fmt::print("warning: {}\n", w);
  }
  return wall;
}

/// One order alone with one sampler (section 5 of the file comment).
void single_order(const Measurement& data, const Order& order, SamplerKind kind, int live, std::uint64_t seed,
                  const NestedSettings& given, int runs) {
  FitSettings s;
  s.runs = runs;
  s.sampler = given;
  s.sampler_kind = kind;
  s.sampler.live = live;
  s.sampler.seed = seed;
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  const ModelResult m = fit_order(data, order, s);
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  fmt::print("{} ({} points, {} live, seed {}): {:.3f} s wall, {:.3f} s CPU, {} calls, {} iterations, {:.0f} ns/call "
             "(CPU), ln Z {:.2f} ± {:.2f}, sampler {}\n",
             order.name(), data.size(), live, seed, wall, cpu, m.run.calls, m.run.iterations,
             cpu * 1e9 / static_cast<double>(m.run.calls), m.run.log_z, m.run.log_z_error, m.sampler);
  if (!m.sampler_note.empty()) fmt::print("  {}\n", m.sampler_note);
}

/// One order over `seeds` seeds (section 6 of the file comment).
void seed_spread(const Measurement& data, const Order& order, SamplerKind kind, int live, std::uint64_t seed,
                 int seeds, const NestedSettings& given, int runs_per_order) {
  FitSettings s;
  s.runs = runs_per_order;
  s.sampler = given;
  s.sampler_kind = kind;
  s.sampler.live = live;
  std::vector<ModelResult> runs;
  for (int k = 0; k < seeds; ++k) runs.push_back(ModelResult{Order(0, 0), {}, 0, 0.0, {}});
  std::vector<std::size_t> queue(static_cast<std::size_t>(seeds));
  for (std::size_t k = 0; k < queue.size(); ++k) queue[k] = k;
  run_in_parallel(queue, 2, [&](std::size_t k) {
    FitSettings mine = s;
    mine.sampler.seed = seed + k;
    runs[k] = fit_order(data, order, mine);
  });
  double mean = 0.0, error = 0.0, calls = 0.0;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const ModelResult& m = runs[k];
    fmt::print("{} seed {}: ln Z {:.3f} ± {:.3f}, {} calls, {} iterations\n", order.name(), seed + k, m.run.log_z,
               m.run.log_z_error, m.run.calls, m.run.iterations);
    mean += m.run.log_z;
    error += m.run.log_z_error;
    calls += static_cast<double>(m.run.calls);
  }
  const double n = static_cast<double>(seeds);
  mean /= n, error /= n, calls /= n;
  double variance = 0.0;
  for (const ModelResult& m : runs) variance += (m.run.log_z - mean) * (m.run.log_z - mean);
  const double sd = std::sqrt(variance / std::max(n - 1.0, 1.0));
  // The standard deviation of n values has a relative standard error of about 1/√(2(n − 1)).
  fmt::print("{} over {} seeds ({} live, {} runs each): mean ln Z {:.3f} ± {:.3f} (standard error), spread {:.3f} (± {:.0f} %) against "
             "the mean reported error {:.3f}: {:.2f}x; mean calls {:.0f}\n",
             order.name(), seeds, live, s.runs, mean, sd / std::sqrt(n), sd, 100.0 / std::sqrt(2.0 * std::max(n - 1.0, 1.0)),
             error, sd / error, calls);
}

}  // namespace

int main(int argc, char** argv) {
  std::string path = std::string(ADMITGEN_SAMPLES) + "/reference/q1s1_sigma0.01.csv";
  bool quick = false, basotect = false;
  std::string order_name;
  int live = 100;
  std::uint64_t seed = 1;
  int seeds = 0;
  SamplerKind single_kind = SamplerKind::poles;
  NestedSettings chosen;  // --slices and --dlogz of sections 5-6
  int runs = FitSettings{}.runs;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    else if (std::strcmp(argv[i], "--basotect") == 0) basotect = true;
    else if (std::strcmp(argv[i], "--order") == 0 && has_value) order_name = argv[++i];
    else if (std::strcmp(argv[i], "--live") == 0 && has_value) live = std::stoi(argv[++i]);
    else if (std::strcmp(argv[i], "--seed") == 0 && has_value) seed = std::stoull(argv[++i]);
    else if (std::strcmp(argv[i], "--seeds") == 0 && has_value) seeds = std::stoi(argv[++i]);
    else if (std::strcmp(argv[i], "--sampler") == 0 && has_value) single_kind = parse_sampler_kind(argv[++i]);
    else if (std::strcmp(argv[i], "--slices") == 0 && has_value) chosen.slices = std::stoi(argv[++i]);
    else if (std::strcmp(argv[i], "--dlogz") == 0 && has_value) chosen.dlogz = std::stod(argv[++i]);
    else if (std::strcmp(argv[i], "--runs") == 0 && has_value) runs = std::stoi(argv[++i]);
    else path = argv[i];
  }
  const std::string quick_start = std::string(ADMITGEN_SAMPLES) + "/basotect_tuberlin/round_10cm.csv";
  ReadOptions foam_options{};
  foam_options.columns = ColumnMap::parse("f,_,_,_,_,re,im,_");
  if (!order_name.empty()) {
    const Measurement data = basotect ? read_measurement(quick_start, foam_options) : read_measurement(path, ReadOptions{});
    if (seeds > 0) seed_spread(data, Order::parse(order_name), single_kind, live, seed, seeds, chosen, runs);
    else single_order(data, Order::parse(order_name), single_kind, live, seed, chosen, runs);
    return 0;
  }
  const Measurement data = read_measurement(path, ReadOptions{});
  fmt::print("SIMD path of the pole sampler's normal equations: {}\n", residue_gram_isa());
  likelihood_throughput(data);
  // Each sampler in turn, in one run (figures side by side; "used" says which sampler ran per order).
  for (const SamplerKind kind : {SamplerKind::full, SamplerKind::poles}) {
    const char* name = kind == SamplerKind::full ? "full" : "poles";
    fmt::print("\n## Q1S1 alone, sampler {} (500 live points)\n", name);
    const auto t0 = Clock::now();
    FitSettings s;
    s.sampler_kind = kind;
    const ModelResult m = fit_order(data, Order(1, 1), s);
    fmt::print("Q1S1: {:.2f} s wall, {:.2f} s CPU, {} calls, ln Z {:.2f} ± {:.2f}\n",
               std::chrono::duration<double>(Clock::now() - t0).count(), m.cpu_seconds, m.run.calls, m.run.log_z,
               m.run.log_z_error);
    fmt::print("\n## Q0-3 x S0-3 grid on {}, sampler {} (500 live points, default band priors, both samplers under the same "
               "Gaussian residue prior, seed 1)\n", path, name);
    const double two = grid(data, 2, true, kind);
    fmt::print("grid wall time, sampler {}, 2 threads: {:.2f} s\n", name, two);
    if (!quick) {
      const double one = grid(data, 1, false, kind);
      fmt::print("grid wall time, sampler {}, 1 thread:  {:.2f} s  (speed-up {:.2f}x)\n", name, one, one / two);
    }
  }
  if (basotect) {
    const Measurement foam = read_measurement(quick_start, foam_options);
    for (const SamplerKind kind : {SamplerKind::full, SamplerKind::poles}) {
      const char* name = kind == SamplerKind::full ? "full" : "poles";
      fmt::print("\n## Quick start: {} ({} points), sampler {} (100 live points, 2 threads)\n", quick_start, foam.size(),
                 name);
      const double wall = grid(foam, 2, true, kind, 3, 3, 100);
      fmt::print("quick-start wall time, sampler {}: {:.2f} s\n", name, wall);
    }
  }
  return 0;
}

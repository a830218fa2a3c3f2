// SPDX-License-Identifier: MIT
/// @file
/// Diagnose benchmark (a program, not a test). One single-effect diagnosis of 1000 points: a layered
/// absorber (JCA foam 30 mm on a 20 mm air gap) measured in a 29 mm tube (s = 20 mm, x1 = 50 mm) from
/// 50 Hz to 4 kHz, with a frame resonance (f0 800 Hz, q 8, y_peak 0.1) and noise σ = 0.003, diagnosed
/// against the clean material: 11 candidate effects, 100 live points, seed 1. Prints per-candidate
/// method, likelihood calls, seconds and Bayes factor, and the wall time of each configuration:
///   baseline   every candidate with parameters sampled, 1 thread, no early stop (the former method);
///   1 thread   quadrature for 0-1 parameters, early stop;
///   N threads  the same on 2 threads and on all cores (results identical; checked here).
/// Usage: bench_diagnose [--points N] [--threads N]   (the last configuration's thread count; default all)
#include "diagnosis/diagnosis.hpp"
#include "diagnosis/diagnosis_record.hpp"
#include "io/diagnosis_file.hpp"
#include "physics/material_spec.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

using namespace admitgen;
using Clock = std::chrono::steady_clock;

namespace {

diagnosis::DiagnosisRequest single_effect_case(int points) {
  const std::string spec =
      "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)";
  const TubeSetup tube{0.029, 0.02, 0.05, 20.0};
  SynthesisRequest s{parse_material_spec(spec), {parse_effect("frame_resonance:f0_hz=800,q=8,y_peak=0.1")},
                     log_spaced_frequencies(50.0, 4000.0, points), 0.003, 3, tube};
  Measurement real;
  real.path = "bench";
  real.f_hz = s.f_hz;
  real.y = synthesize(s).y;
  return {real, diagnosis::SimulatedSide::from_material(s.material, Air::at_celsius(20.0), spec), tube, {},
          std::nullopt};
}

struct Timed {
  diagnosis::Diagnosis result;
  double seconds;
};

Timed run(diagnosis::DiagnosisRequest request, int threads, bool former) {
  request.settings.threads = threads;
  if (former) {
    request.settings.use_quadrature = false;
    request.settings.early_stop_deciban = 0.0;
  }
  const auto t0 = Clock::now();
  diagnosis::Diagnosis d = diagnosis::run_diagnosis(request);
  return {std::move(d), std::chrono::duration<double>(Clock::now() - t0).count()};
}

void print_candidates(const diagnosis::Diagnosis& d) {
  fmt::print("{:<22} {:>4} {:<16} {:>9} {:>8} {:>8} {:>10}  {}\n", "candidate", "dim", "method", "calls", "wall s",
             "cpu s", "BF [dB]", "");
  double cpu = 0.0;
  for (const auto& e : d.identification.effects) {
    fmt::print("{:<22} {:>4} {:<16} {:>9} {:>8.3f} {:>8.3f} {:>10.1f}  {}\n", e.name, e.priors.size(), e.method, e.calls,
               e.seconds, e.cpu_seconds, e.bayes_factor_deciban, e.stopped_early ? "stopped early" : "");
    cpu += e.cpu_seconds;
  }
  fmt::print("candidates' CPU time {:.2f} s\n", cpu);
  fmt::print("verdict: {} (BF {:.1f} dB)\n", d.verdict.effect, d.verdict.bayes_factor_deciban);
}

}  // namespace

int main(int argc, char** argv) {
  int points = 1000, threads = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--points") == 0) points = std::atoi(argv[i + 1]);
    else if (std::strcmp(argv[i], "--threads") == 0) threads = std::atoi(argv[i + 1]);
  }
  const auto request = single_effect_case(points);
  fmt::print("# diagnose: {} points 50-4000 Hz, frame resonance on a layered absorber, {} cores\n", points,
             std::thread::hardware_concurrency());

  fmt::print("\n## baseline: every candidate sampled, 1 thread, no early stop\n");
  const Timed former = run(request, 1, true);
  print_candidates(former.result);
  fmt::print("\n## quadrature for 0-1 parameters, early stop, 1 thread\n");
  const Timed one = run(request, 1, false);
  print_candidates(one.result);
  const Timed two = run(request, 2, false);
  const Timed all = run(request, threads, false);
  const std::string text = io::diagnosis_text(diagnosis::diagnosis_record(one.result));
  const bool identical = text == io::diagnosis_text(diagnosis::diagnosis_record(two.result)) &&
                         text == io::diagnosis_text(diagnosis::diagnosis_record(all.result));

  fmt::print("\n## wall time\n");
  fmt::print("baseline (former method, 1 thread)  {:7.2f} s\n", former.seconds);
  fmt::print("new, 1 thread                       {:7.2f} s  ({:.1f}x faster than the baseline)\n", one.seconds,
             former.seconds / one.seconds);
  fmt::print("new, 2 threads                      {:7.2f} s  ({:.1f}x; {:.2f}x over 1 thread)\n", two.seconds,
             former.seconds / two.seconds, one.seconds / two.seconds);
  fmt::print("new, {} threads{:<22}{:7.2f} s  ({:.1f}x)\n", threads == 0 ? std::string("all") : std::to_string(threads),
             "", all.seconds, former.seconds / all.seconds);
  fmt::print("diagnosis.json identical across thread counts: {}\n", identical ? "yes" : "NO");
  fmt::print("same verdict as the baseline: {}\n", former.result.verdict.effect == one.result.verdict.effect ? "yes" : "NO");
  return identical ? 0 : 1;
}

// SPDX-License-Identifier: MIT
/// @file
/// Diagnose benchmark (a program, not a test). Two 1000-point diagnoses of a layered absorber (JCA foam
/// 30 mm on a 20 mm air gap) measured in a 29 mm tube (s = 20 mm, x1 = 50 mm) from 50 Hz to 4 kHz, with
/// noise σ = 0.003, diagnosed against the clean material SPEC (so with its 7 `material` candidates), 100
/// live points, seed 1:
///   single    a frame resonance (f0 800 Hz, q 8, y_peak 0.1): one effect, whose residual is white, then
///             the one round that tries the noise shape;
///   combined  a microphone spacing error (1 mm) and an edge gap (0.5 mm wide, 30 mm deep): the combined
///             search runs a round of every remaining effect jointly with the first (the two-effect case);
///   triple    the same two and a frame resonance (f0 800 Hz, q 8, y_peak 0.1): three members, with the
///             swap and backward steps of the combined search (the three-effect case);
///   four      the same three and a microphone mismatch (gain 3 %, phase 1°): four members (the
///             four-effect case).
/// Targets (docs/diagnosis.md, "Speed"): single ≤ 3 s, two effects ≤ 10 s, three ≤ 20 s, four ≤ 40 s of wall
/// time on 2 cores; printed, not asserted (a shared machine's wall time is no test).
/// Prints per-candidate method, likelihood calls, seconds and Bayes factor, the joint candidates of each
/// round of the combined search, and the wall time of each configuration:
///   baseline   every candidate with parameters sampled, 1 thread, no early stop (the former method;
///              single case only, skipped with --no-baseline);
///   1 thread   quadrature for 0-1 parameters, early stop;
///   N threads  the same on 2 threads and on N (results identical; checked here).
/// Usage: bench_diagnose [--points N] [--threads N] [--case single|combined|triple|four|both|all] [--no-baseline] [--once]
///   (both: single and combined, the default; all: the four cases)
///   (--once: only the run on --threads threads, with its per-candidate table: CPU figures on a busy machine)
#include "diagnosis/diagnosis.hpp"
#include "diagnosis/diagnosis_record.hpp"
#include "inference/evidence.hpp"
#include "io/diagnosis_file.hpp"
#include "physics/material_spec.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

using namespace admitgen;
using Clock = std::chrono::steady_clock;

namespace {

diagnosis::DiagnosisRequest bench_case(int points, const std::vector<std::string>& effects) {
  const std::string spec =
      "jca(phi=0.94, sigma=40000, alpha_inf=1.06, lambda=56um, lambda_th=110um, d=30mm) + air(d=20mm)";
  const TubeSetup tube{0.029, 0.02, 0.05, 20.0};
  std::vector<Effect> parsed;
  for (const auto& e : effects) parsed.push_back(parse_effect(e));
  SynthesisRequest s{parse_material_spec(spec), parsed, log_spaced_frequencies(50.0, 4000.0, points), 0.003, 3, tube};
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

/// One table row per candidate (Bayes factor against no effect, ln Z₀ = log_z_none); returns the sum of
/// their CPU seconds.
double print_results(const std::vector<diagnosis::EffectResult>& results, double log_z_none) {
  fmt::print("{:<40} {:>4} {:<16} {:>9} {:>8} {:>8} {:>10}  {}\n", "candidate", "dim", "method", "calls", "wall s",
             "cpu s", "BF [dB]", "");
  double cpu = 0.0;
  for (const auto& e : results) {
    const std::string name = e.name == "material" && !e.priors.empty() ? e.name + " " + e.priors.front().name : e.name;
    fmt::print("{:<40} {:>4} {:<16} {:>9} {:>8.3f} {:>8.3f} {:>10.1f}  {}\n", name, e.priors.size(), e.method, e.calls,
               e.seconds, e.cpu_seconds, deciban(e.log_z, log_z_none), e.stopped_early ? "stopped early" : "");
    cpu += e.cpu_seconds;
  }
  return cpu;
}

void print_diagnosis(const diagnosis::Diagnosis& d) {
  double cpu = print_results(d.identification.effects, d.identification.log_z_none);
  fmt::print("single effects' CPU time {:.2f} s\n", cpu);
  for (std::size_t r = 0; r < d.explanation.rounds.size(); ++r) {
    fmt::print("combined search, round {} (BF against none):\n", r + 1);
    const double round_cpu = print_results(d.explanation.rounds[r], d.identification.log_z_none);
    fmt::print("round {} CPU time {:.2f} s\n", r + 1, round_cpu);
    cpu += round_cpu;
  }
  std::string members;
  for (const auto& m : d.verdict.explanation) members += (members.empty() ? "" : " + ") + m.effect;
  fmt::print("candidates' CPU time {:.2f} s; verdict: {} (BF {:.1f} dB), explanation: {}\n", cpu, d.verdict.effect,
             d.verdict.bayes_factor_deciban, members);
}

std::string json(const diagnosis::Diagnosis& d) { return io::diagnosis_text(diagnosis::diagnosis_record(d)); }

/// The new method on 1, 2 and `threads` threads (wall times; results checked identical). Returns whether
/// they are.
bool bench_new(const diagnosis::DiagnosisRequest& request, int threads, const Timed* baseline, bool once) {
  if (once) {
    const Timed t = run(request, threads, false);
    fmt::print("\n## quadrature for 0-1 parameters, early stop, {} threads\n", threads);
    print_diagnosis(t.result);
    fmt::print("wall time {:.2f} s\n", t.seconds);
    std::fflush(stdout);
    return true;
  }
  const Timed one = run(request, 1, false);
  fmt::print("\n## quadrature for 0-1 parameters, early stop, 1 thread\n");
  print_diagnosis(one.result);
  const Timed two = run(request, 2, false);
  const Timed all = run(request, threads, false);
  const bool identical = json(one.result) == json(two.result) && json(one.result) == json(all.result);
  const auto ratio = [&](double s) {
    return baseline ? fmt::format("  ({:.1f}x faster than the baseline)", baseline->seconds / s) : std::string();
  };
  fmt::print("\n## wall time\n");
  if (baseline) fmt::print("baseline (former method, 1 thread)  {:7.2f} s\n", baseline->seconds);
  fmt::print("new, 1 thread                       {:7.2f} s{}\n", one.seconds, ratio(one.seconds));
  fmt::print("new, 2 threads                      {:7.2f} s{}; {:.2f}x over 1 thread\n", two.seconds, ratio(two.seconds),
             one.seconds / two.seconds);
  fmt::print("new, {:<3} threads                    {:7.2f} s{}\n",
             threads == 0 ? std::string("all") : std::to_string(threads), all.seconds, ratio(all.seconds));
  fmt::print("diagnosis.json identical across thread counts: {}\n", identical ? "yes" : "NO");
  if (baseline)
    fmt::print("same verdict as the baseline: {}\n",
               baseline->result.verdict.effect == one.result.verdict.effect ? "yes" : "NO");
  std::fflush(stdout);
  return identical;
}

}  // namespace

int main(int argc, char** argv) {
  int points = 1000, threads = 0;
  std::string which = "both";
  bool baseline = true, once = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--no-baseline") == 0) baseline = false;
    else if (std::strcmp(argv[i], "--once") == 0) once = true;
    else if (i + 1 < argc && std::strcmp(argv[i], "--points") == 0) points = std::atoi(argv[++i]);
    else if (i + 1 < argc && std::strcmp(argv[i], "--threads") == 0) threads = std::atoi(argv[++i]);
    else if (i + 1 < argc && std::strcmp(argv[i], "--case") == 0) which = argv[++i];
  }
  fmt::print("# diagnose: {} points 50-4000 Hz, layered absorber against its SPEC, {} cores\n", points,
             std::thread::hardware_concurrency());
  bool identical = true;
  if (which == "single" || which == "both" || which == "all") {
    fmt::print("\n# single: a frame resonance\n");
    const auto request = bench_case(points, {"frame_resonance:f0_hz=800,q=8,y_peak=0.1"});
    std::optional<Timed> former;
    if (baseline && !once) {
      fmt::print("\n## baseline: every candidate sampled, 1 thread, no early stop\n");
      former = run(request, 1, true);
      print_diagnosis(former->result);
    }
    identical = bench_new(request, threads, former ? &*former : nullptr, once) && identical;
  }
  if (which == "combined" || which == "both" || which == "all") {
    fmt::print("\n# combined: a microphone spacing error and an edge gap\n");
    const auto request = bench_case(points, {"mic_spacing:delta_m=1mm", "edge_gap:width_m=0.5mm,depth_m=30mm"});
    identical = bench_new(request, threads, nullptr, once) && identical;
  }
  if (which == "triple" || which == "all") {
    fmt::print("\n# triple: a microphone spacing error, an edge gap and a frame resonance\n");
    const auto request = bench_case(points, {"mic_spacing:delta_m=1mm", "edge_gap:width_m=0.5mm,depth_m=30mm",
                                             "frame_resonance:f0_hz=800,q=8,y_peak=0.1"});
    identical = bench_new(request, threads, nullptr, once) && identical;
  }
  if (which == "four" || which == "all") {
    fmt::print("\n# four: a microphone spacing error, an edge gap, a frame resonance and a microphone mismatch\n");
    const auto request = bench_case(points, {"mic_spacing:delta_m=1mm", "mic_mismatch:gain=0.03,phase_deg=1",
                                             "edge_gap:width_m=0.5mm,depth_m=30mm", "frame_resonance:f0_hz=800,q=8,y_peak=0.1"});
    identical = bench_new(request, threads, nullptr, once) && identical;
  }
  return identical ? 0 : 1;
}

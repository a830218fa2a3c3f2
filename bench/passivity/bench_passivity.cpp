// SPDX-License-Identifier: MIT
/// @file
/// Passivity benchmark (a program, not a test; docs/passivity.md). For each data set it runs a fit and
/// prints, measured in the same run:
///  1. the fit's wall time and the share of it spent on the passive estimates of every order;
///  2. emit at 44.1, 48 and 96 kHz in f32, q31 and q15: the certified pipeline (passive refit, checks
///     of the header as written) against a plain least-squares emit with the same checks, and the extra
///     time as a fraction of the fit.
/// Usage: bench_passivity [--full]   (--full adds the 1025-point Basotect file over Q0-3 x S0-3; minutes)
#include "codegen/template_text.hpp"
#include "checks/check_suite.hpp"
#include "core/progress.hpp"
#include "data/csv_reader.hpp"
#include "emit/emit.hpp"
#include "io/check_input.hpp"
#include "io/fit_file.hpp"
#include "io/model_block.hpp"
#include "selection/fit_record.hpp"
#include "selection/fit.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cstring>
#include <string>

using namespace admitgen;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void run(const std::string& label, const std::string& path, const std::string& columns, int qmax, int smax) {
  ReadOptions read;
  read.columns = ColumnMap::parse(columns);
  const Measurement data = read_measurement(path, read);
  FitSettings settings;
  settings.qmax = qmax;
  settings.smax = smax;
  settings.sampler.live = 100;
  settings.threads = 2;
  Progress quiet(false);
  auto t = Clock::now();
  FitResult fit = run_fit(data, settings, quiet);
  const double fit_s = seconds_since(t);
  t = Clock::now();
  for (auto& m : fit.models)
    m.passive = passivity::passive_estimate(data, m.order, best_samples(m, passivity::PassiveEstimate::kCandidates),
                                            settings.data_count);
  const double passive_s = seconds_since(t);
  fmt::print("{}: {} points, Q0-{} x S0-{}, 100 live, 2 threads\n", label, data.size(), qmax, smax);
  fmt::print("  fit (incl. passive estimates)   {:8.3f} s\n", fit_s);
  fmt::print("  passive estimates, all orders   {:8.3f} s  ({:.1f} % of the fit, single thread)\n", passive_s,
             100.0 * passive_s / fit_s);

  const auto json = io::parse_fit(io::fit_text(fit_record(data, read, settings, fit)), "fit.json");
  const std::string tpl = codegen::load_template("", "admitgen_boundary.h.in");
  double certified_s = 0.0, plain_s = 0.0;
  int safe = 0, plain_safe = 0, total = 0;
  for (auto format : {codegen::Format::f32, codegen::Format::q31, codegen::Format::q15}) {
    codegen::EmitSettings s;
    s.fs_hz = {44100.0, 48000.0, 96000.0};
    s.format = format;
    s.name = "wall";
    t = Clock::now();
    const auto r = emit::emit(json, "fit.json", s, tpl, "wall.h");
    certified_s += seconds_since(t);
    safe += r.safe();
    // Plain: the same estimate and checks, least-squares refit without passivity constraints.
    t = Clock::now();
    const auto e = codegen::prepare_emission(json, "fit.json", s);
    const auto header = io::header_text(e, tpl, "wall.h");
    plain_safe += checks::run_checks(io::header_subject(header, "wall.h")).passed();
    plain_s += seconds_since(t);
    ++total;
  }
  fmt::print("  emit 3 rates x 3 formats: certified {:.3f} s ({}/{} pass check), plain {:.3f} s ({}/{} pass check)\n",
             certified_s, safe, total, plain_s, plain_safe, total);
  fmt::print("  extra time of enforcement and refit: {:.3f} s = {:.1f} % of the fit (goal <= 10 %)\n\n",
             passive_s + certified_s - plain_s, 100.0 * (passive_s + certified_s - plain_s) / fit_s);
}

}  // namespace

int main(int argc, char** argv) {
  const bool full = argc > 1 && std::strcmp(argv[1], "--full") == 0;
  const std::string s = ADMITGEN_SAMPLES;
  run("reference (synthetic Q1S1)", s + "/reference/q1s1_sigma0.01.csv", "f,re,im", 3, 3);
  run("three-layer MPP (synthetic)", s + "/synthetic/mpp_three_layer.csv", "f,re,im", 1, 3);
  run("Basotect rect 10 cm (real), reduced grid", s + "/basotect_tuberlin/rect_10cm.csv", "f,_,_,_,_,re,im,_", 1, 2);
  if (full) run("Basotect round 10 cm (real)", s + "/basotect_tuberlin/round_10cm.csv", "f,_,_,_,_,re,im,_", 3, 3);
  return 0;
}

// SPDX-License-Identifier: MIT
#include "diagnosis/stage_attribution.hpp"

#include "codegen/emission.hpp"
#include "core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace admitgen::diagnosis {
namespace {

Eigen::ArrayXcd response(const codegen::DiscreteModel& model, const Eigen::ArrayXd& f_hz) {
  Eigen::ArrayXcd h(f_hz.size());
  for (Eigen::Index i = 0; i < f_hz.size(); ++i) h[i] = model.response(f_hz[i]);
  return h;
}

StageGap stage(const std::string& name, const Eigen::ArrayXd& f, const Eigen::ArrayXcd& y_real,
               const Eigen::ArrayXcd& before, const Eigen::ArrayXcd& after, double level, std::string detail = {}) {
  return {name, measure_gap(f, before, after, level), measure_gap(f, y_real, after, level), std::move(detail)};
}

simulation::TubeSimulationSettings tube_settings(const StageRequest& request, double f_max) {
  simulation::TubeSimulationSettings s;
  s.c0 = Air::at_celsius(request.tube.temperature_c).c0;
  s.window_s = request.sim_window_s;
  const double h = s.c0 / request.fs_hz;
  s.spacing_m = request.tube.spacing_m.value_or(std::max(1.0, std::floor(std::min(0.05, 0.4 * s.c0 / f_max) / h)) * h);
  s.mic1_distance_m = request.tube.mic1_distance_m.value_or(2.0 * s.spacing_m);
  return s;
}

}  // namespace

std::vector<StageGap> attribute_stages(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
                                       const StageRequest& request) {
  const double f_max = f_hz[f_hz.size() - 1];
  if (!(f_max < 0.45 * request.fs_hz))
    throw InputError(fmt::format("{}: the data reach {:g} Hz, above 0.45 fs; raise {} or narrow {}",
                                 setting("fs_hz", fmt::format("{:g}", request.fs_hz)), f_max, setting("fs_hz"),
                                 setting("band")));
  codegen::EmitSettings settings;
  settings.fs_hz = {request.fs_hz};
  settings.format = request.format;
  settings.name = "diagnose";
  // The stages are those of the fit's posterior mean discretised by least squares: what each stage of the
  // pipeline costs, without the passivity enforcement emit adds (docs/passivity.md) on top.
  settings.estimate = Estimate::mean;
  const codegen::Emission emission = codegen::prepare_emission(request.fit, request.fit_path, settings);
  const codegen::EmittedRate& rate = emission.rates.front();

  const double level = rms_level(y_real);
  const Eigen::ArrayXcd y_fit = surface_admittance(emission.surface, f_hz);
  const Eigen::ArrayXcd y_discrete = response(rate.model, f_hz);
  const Eigen::ArrayXcd y_emitted = response(rate.emitted_model(), f_hz);

  std::vector<StageGap> out;
  out.push_back(stage("fit", f_hz, y_real, y_real, y_fit, level));
  out.push_back(stage("discretization", f_hz, y_real, y_fit, y_discrete, level));
  out.push_back(stage("quantization", f_hz, y_real, y_discrete, y_emitted, level));
  const auto sim = simulation::simulate_impedance_tube(rate, request.format, f_hz, tube_settings(request, f_max));
  out.push_back(stage("simulation", f_hz, y_real, y_emitted, sim.y, level,
                      fmt::format("1D FDTD tube at {:g} Hz (cell {:.3g} mm), {} runtime, mics at x1 = {:.4g} m, s = {:.4g} m, "
                                  "{} samples ({}){}",
                                  request.fs_hz, 1e3 * sim.x1_m / sim.m1, codegen::format_name(request.format), sim.x1_m,
                                  sim.spacing_m, sim.samples, sim.decayed ? "decayed" : "window cut",
                                  sim.saturated_inputs ? fmt::format(", {} saturated inputs", sim.saturated_inputs) : "")));
  return out;
}

}  // namespace admitgen::diagnosis

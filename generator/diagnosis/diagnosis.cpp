// SPDX-License-Identifier: MIT
#include "diagnosis/diagnosis.hpp"

#include "core/errors.hpp"
#include "core/progress.hpp"
#include "data/csv_reader.hpp"

#include <fmt/format.h>

#include <vector>

namespace admitgen::diagnosis {
namespace {

/// The measured points where the simulated side is known (a simulated table may cover less).
Measurement covered_part(const Measurement& real, const SimulatedSide& sim, std::vector<std::string>& warnings) {
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < real.size(); ++i)
    if (sim.covers(real.f_hz[i])) keep.push_back(i);
  if (static_cast<int>(keep.size()) < kMinimumPoints)
    throw InputError(fmt::format("{}: only {} measured points lie inside the simulated range ({}); need at least {}",
                                 real.path, keep.size(), sim.description(), kMinimumPoints));
  Measurement out = real;
  if (keep.size() == static_cast<std::size_t>(real.size())) return out;
  warnings.push_back(fmt::format("{} of {} measured points lie outside the simulated range and are left out",
                                 real.size() - static_cast<Eigen::Index>(keep.size()), real.size()));
  out.f_hz.resize(static_cast<Eigen::Index>(keep.size()));
  out.y.resize(static_cast<Eigen::Index>(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k) {
    out.f_hz[static_cast<Eigen::Index>(k)] = real.f_hz[keep[k]];
    out.y[static_cast<Eigen::Index>(k)] = real.y[keep[k]];
  }
  return out;
}

}  // namespace

Diagnosis run_diagnosis(const DiagnosisRequest& request) {
  Progress silent(false);
  return run_diagnosis(request, silent);
}

Diagnosis run_diagnosis(const DiagnosisRequest& request, Progress& progress) {
  Diagnosis d;
  d.real_path = request.real.path;
  d.real_sha256 = request.real.sha256;
  d.sim_description = request.sim.description();
  d.settings = request.settings;
  d.warnings = request.real.warnings;
  const Measurement real = covered_part(request.real, request.sim, d.warnings);
  d.f_hz = real.f_hz;
  d.level = rms_level(real.y);
  if (!(d.level > 0.0)) throw InputError(fmt::format("{}: the measured admittance is zero everywhere", real.path));
  const Eigen::ArrayXcd y_sim = request.sim.admittance(real.f_hz);
  d.gap = measure_gap(real.f_hz, real.y, y_sim, d.level);
  if (request.stages) d.stages = attribute_stages(real.f_hz, real.y, *request.stages);
  d.candidates = effect_candidates(real.f_hz, y_sim, request.sim, request.tube);
  d.identification = identify_effects(real.f_hz, real.y, y_sim, d.gap, d.candidates, request.settings, progress);
  d.explanation = explain(real.f_hz, real.y, y_sim, d.gap, d.candidates, d.identification, request.settings, progress);
  d.verdict = decide(d.gap, d.identification, d.explanation, d.candidates);
  return d;
}

}  // namespace admitgen::diagnosis

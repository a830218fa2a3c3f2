// SPDX-License-Identifier: MIT
/// @file
/// `admitgen emit` as a library call, with its safety rule (docs/passivity.md):
///
///  1. the continuous model is read from the fit (default: its passive estimate); if that estimate is
///     not passive, its residues are changed minimally (least squares at the data frequencies, subject to
///     Re G ≥ 0 at every frequency; passivity/passive_residues.hpp) and the change is stamped in the header;
///  2. at every rate the discrete refit is constrained to Re H ≥ 0 up to Nyquist and certified by the
///     discrete Hamiltonian test (codegen/discrete_model.hpp, checks/passivity.hpp);
///  3. the header is rendered and checked exactly as written (admitgen check). When coefficient rounding
///     to the format breaks the certificate, the refit is repeated with a larger margin;
///  4. a header that still fails a check is not safe: EmitResult::refusal() says why and what to run next.
#pragma once

#include "checks/report.hpp"
#include "codegen/emission.hpp"
#include "model/fit_record.hpp"

#include <string>
#include <vector>

namespace admitgen::emit {

struct EmitResult {
  codegen::Emission emission;
  std::string header;         ///< the header text, exactly as checked
  checks::CheckReport report; ///< admitgen check of that text
  bool safe() const { return report.passed(); }
  /// Empty when safe; otherwise the failures and the next step to take, for a header written to `out`.
  /// The advice names settings (core/errors.hpp, setting()): plain_settings() reads them by their keys,
  /// the command line spells them as its flags.
  std::string refusal(const std::string& out) const;
};

/// Everything `admitgen emit` computes, before anything is written. Throws InputError on bad input.
EmitResult emit(const FitRecord& fit, const std::string& fit_path, codegen::EmitSettings settings,
                const std::string& template_text, const std::string& header_file_name);

/// The same from a continuous model already read (steps 1-4).
EmitResult emit(codegen::EmissionSource source, codegen::EmitSettings settings, const std::string& template_text,
                const std::string& header_file_name);

/// Step 2's certifier (what the discrete refit is given): for each band of the filter where Re H < 0
/// (discrete Hamiltonian test), its minimum and 9 points spanning it, in Hz; empty when passive up to Nyquist.
std::vector<double> discrete_passivity_violations(const codegen::DiscreteModel& model);

/// Step 1 alone: makes `source.surface` passive if it is not, recording the change in source.notes and
/// source.enforcement (unchanged and no note when it already is passive).
void enforce_continuous_passivity(codegen::EmissionSource& source);

}  // namespace admitgen::emit

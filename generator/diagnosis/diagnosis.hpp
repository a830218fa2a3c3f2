// SPDX-License-Identifier: MIT
/// @file
/// `admitgen diagnose` as a library: where the sim-to-real gap lies (gap_metrics), which pipeline
/// stage adds it (stage_attribution, with a fit), which unmodelled effect causes it
/// (effect_identification), which effects together (explanation.hpp) and the verdict (verdict.hpp). The
/// procedure follows docs/physics.md §5.0: gap and its whiteness → evidence of each effect added to the
/// simulated side → the decisively supported one, effects added to it while each is decisive → how far
/// the gap shrinks and whether the residual is white.
#pragma once

#include "data/measurement.hpp"
#include "diagnosis/effect_identification.hpp"
#include "diagnosis/simulated_side.hpp"
#include "diagnosis/stage_attribution.hpp"
#include "diagnosis/verdict.hpp"
#include "physics/synthetic_measurement.hpp"

#include <optional>
#include <string>
#include <vector>

namespace admitgen::diagnosis {

struct DiagnosisRequest {
  Measurement real;
  SimulatedSide sim;
  TubeSetup tube;
  IdentificationSettings settings;
  std::optional<StageRequest> stages;  ///< with --fit and --fs
};

struct Diagnosis {
  std::string real_path, real_sha256, sim_description;
  Eigen::ArrayXd f_hz;  ///< the measured frequencies the simulated side covers
  double level = 0.0;   ///< ‖y_real‖, the gap's denominator
  Gap gap;
  std::vector<StageGap> stages;
  std::vector<EffectCandidate> candidates;  ///< what was tried (priors for the report)
  Identification identification;
  Explanation explanation;
  Verdict verdict;
  IdentificationSettings settings;
  std::vector<std::string> warnings;
};

/// Runs the whole diagnosis, with progress on `progress` (a terminal's stderr). Deterministic for a given
/// request, whatever settings.threads. Throws InputError if fewer than kMinimumPoints measured points lie
/// where the simulated side is known.
Diagnosis run_diagnosis(const DiagnosisRequest& request, Progress& progress);
/// The same without progress.
Diagnosis run_diagnosis(const DiagnosisRequest& request);

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
/// @file
/// `admitgen diagnose --real FILE` without a simulation: physics is the reference (docs/diagnosis.md,
/// "Physics as the reference"). Every wall is causal and passive, so the closest passive causal admittance
/// (numerics/passive_bound.hpp) is the reference side. Each measurement-chain effect (reference_plane,
/// mic_spacing, mic_mismatch, temperature, tube_losses; reference_plane alone without a tube geometry) is
/// undone on the data (physics/two_microphone.hpp correct_through_chain) over its prior, and the evidence
/// that the corrected data are a passive wall is compared with that of the data as they are:
///
///   ln L(ϑ) = −‖y_ϑ − P(y_ϑ)‖² / σ²,   Z_e = ∫ L(ϑ) π(ϑ) dϑ,   BF_e = 10 log₁₀(Z_e / L(no correction)) dB,
///
/// with P the best passive fit (a profile likelihood over the passive walls) and σ² the complex noise
/// variance per point estimated from the data's second differences (estimate_noise_variance). The integral
/// runs on a grid in the prior's unit cube, refined around its best cell. An effect is named when its BF
/// reaches kDecisiveDeciban (the rule of the other modes); otherwise the data are `consistent` when the
/// passive residual is within kConsistentNoiseRatio × σ, `unexplained` if not.
#pragma once

#include "data/measurement.hpp"
#include "diagnosis/effect_candidates.hpp"
#include "physics/synthetic_measurement.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen::diagnosis {

/// The passive residual's RMS may exceed the noise's by this factor and still be `consistent`: a dense passive
/// dictionary fits part of the noise, so on passive data the ratio stays below 1; 1.5 leaves room for a noise
/// estimate that is low by a third.
inline constexpr double kConsistentNoiseRatio = 1.5;

/// At most this many points enter the passive fits (every k-th of the data): each fit is a non-negative least
/// squares over some 600 terms; 120 points keep one fit near 50 ms.
inline constexpr Eigen::Index kPassiveScanPoints = 120;

struct PassiveEffect {
  std::string name;
  std::vector<ParameterPrior> priors;
  std::vector<double> best;                         ///< max-likelihood correction
  std::vector<double> mean, lo95, hi95;             ///< posterior over the grid
  std::vector<std::string> at_bound;                ///< parameters whose posterior presses on a prior bound
  double bayes_factor_deciban = 0.0;
  double bound_after = 0.0;  ///< relative RMS residual of the best passive fit to the corrected data
  double noise_ratio_after = 0.0;  ///< RMS passive residual / σ after the correction
  int evaluations = 0;
};

struct PassiveDiagnosis {
  std::string real_path, real_sha256;
  Eigen::Index points = 0, scan_points = 0;
  double noise_std = 0.0;     ///< σ: √ of the complex noise variance per point
  double bound_before = 0.0;  ///< relative RMS residual of the best passive fit to the data
  double noise_ratio_before = 0.0;
  double band_lo_hz = 0.0, band_hi_hz = 0.0, band_center_hz = 0.0;  ///< third octave with the largest passive residual
  double band_noise_ratio = 0.0;  ///< that band's RMS passive residual / σ
  std::vector<PassiveEffect> effects;  ///< best Bayes factor first
  std::string verdict;                 ///< consistent | unexplained | an effect's name
  Eigen::ArrayXd f_hz;
  Eigen::ArrayXcd corrected;  ///< the data with the named effect's max-likelihood correction (else as read)
  std::vector<std::string> warnings;
};

/// σ² of complex noise per point from second differences d_i = y_{i−1} − 2y_i + y_{i+1}: for white noise
/// E|d|² = 6σ² and |d|² is exponential, so σ² = median |d|² / (6 ln 2) (the median resists the curvature of a
/// resonance). Needs ≥ 3 points.
double estimate_noise_variance(const Eigen::ArrayXcd& y);

/// The chain effects with their priors for this tube (reference_plane only without a geometry).
std::vector<std::pair<std::string, std::vector<ParameterPrior>>> passive_reference_effects(const TubeSetup& tube);

/// y corrected for effect `name` at ϑ (throws InputError when the correction moves a microphone behind the face).
Eigen::ArrayXcd correct_effect(const std::string& name, const double* theta, const Eigen::ArrayXcd& y,
                               const Eigen::ArrayXd& f_hz, const TubeSetup& tube);

/// The diagnosis above, deterministic whatever `threads` (0 = all cores).
PassiveDiagnosis diagnose_against_passivity(const Measurement& real, const TubeSetup& tube, int threads);

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
/// @file
/// Where the sim-to-real gap lies. With the residual r_i = y_real,i − y_sim,i over N points and the
/// level of the measurement ‖y‖ = (Σ_i |y_real,i|²/N)^{1/2}:
///
///   gap over a set B of points:  g_B = (Σ_{i∈B} |r_i|²/|B|)^{1/2} / ‖y‖
///
/// i.e. the rms complex error relative to the rms admittance of the whole data. The denominator is the
/// same for every band, so bands compare like with like (a band where |y| is small is not blown up by
/// its own noise) and g_all ≈ σ/‖y‖ when only noise of std σ is left. The same with Re r and Im r
/// alone gives the real and imaginary parts (g² = g_re² + g_im²). Absorption difference per band:
/// Δα_max = max_{i∈B} |α_real,i − α_sim,i|, α = 1 − |(1 − y)/(1 + y)|².
#pragma once

#include "diagnosis/residual_whiteness.hpp"
#include "diagnosis/third_octave_bands.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen::diagnosis {

/// The text written as "metric" in diagnosis.json.
inline constexpr const char* kGapMetric =
    "relative complex error: rms|y_real - y_sim| over the band / rms|y_real| over all data";

struct BandGap {
  ThirdOctaveBand band;
  double gap = 0.0;
  double gap_re = 0.0;
  double gap_im = 0.0;
  double delta_alpha_max = 0.0;
};

struct Gap {
  double total = 0.0;
  double total_re = 0.0;
  double total_im = 0.0;
  double delta_alpha_max = 0.0;
  std::vector<BandGap> bands;
  std::size_t worst = 0;  ///< index into bands of the largest gap (first of equals)
  Whiteness whiteness;    ///< of the residual along frequency
};

/// The gap between y_real and y_model at ascending f_hz; `level` is ‖y‖ of the real data (kept fixed
/// when several models are compared with one measurement). Needs ≥ 2 points and one covered band.
Gap measure_gap(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real, const Eigen::ArrayXcd& y_model,
                double level);

/// ‖y‖ = (Σ|y_i|²/N)^{1/2}.
double rms_level(const Eigen::ArrayXcd& y);

/// The band of `bands` where a model explains the most: argmax_b (g_before,b² − g_after,b²).
std::size_t most_improved_band(const std::vector<BandGap>& before, const std::vector<BandGap>& after);

}  // namespace admitgen::diagnosis

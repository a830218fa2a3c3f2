// SPDX-License-Identifier: MIT
/// @file
/// Measurement noise for synthetic data (docs/cli.md): complex Gaussian of std σ, E|n|² = σ², i.e.
/// σ²/2 on each of Re and Im, either the same at every frequency or heteroscedastic the way the
/// two-microphone method amplifies noise (docs/physics.md §5.1 l):
///   σ_i = σ √(1 + (scale/|sin k s|)²),  k = ω/c0, s the microphone spacing.
/// Draws come from core/rng.hpp's Rng (Box-Muller), Re then Im, point by point in the order given,
/// so a seed fixes every bit of the result.
#pragma once

#include "core/rng.hpp"
#include "physics/air.hpp"

#include <Eigen/Core>

namespace admitgen {

/// n_i = σ_i (g_1 + j g_2)/√2 with g standard normal. σ_i ≥ 0 and finite (ENSURE).
Eigen::ArrayXcd complex_gaussian_noise(const Eigen::ArrayXd& std_per_point, Rng& rng);

/// σ_i of the heteroscedastic form. Throws InputError if a frequency sits where sin ks = 0.
Eigen::ArrayXd heteroscedastic_std(double sigma, double scale, const Air& air, double spacing_m,
                                   const Eigen::ArrayXd& f_hz);
/// |sin ks| at f_hz (k = 2πf/c0, s the microphone spacing): what heteroscedastic_std needs of the grid.
Eigen::ArrayXd microphone_sin_ks(const Air& air, double spacing_m, const Eigen::ArrayXd& f_hz);
/// heteroscedastic_std from |sin ks| computed once (same values); infinite where sin ks = 0.
Eigen::ArrayXd heteroscedastic_std(double sigma, double scale, const Eigen::ArrayXd& sin_ks);

}  // namespace admitgen

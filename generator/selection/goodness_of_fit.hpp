// SPDX-License-Identifier: MIT
/// @file
/// How well one order's fit reproduces the data, in the terms scikit-rf and vector fitting report:
/// the relative RMS residual of the complex admittance and the largest absorption error. Both are
/// computed at the order's **maximum-likelihood parameters** (the best point of its nested-sampling
/// run): that is the curve the posterior says fits best, and it exists for every order (the
/// posterior mean of a multimodal posterior need not be a good model).
#pragma once

#include "data/measurement.hpp"
#include "selection/fit.hpp"

#include <optional>
#include <string>

namespace admitgen {

struct GoodnessOfFit {
  /// ‖D − G‖ / ‖D‖ = √(Σ_k |D_k − G_k|² / Σ_k |D_k|²) over the data frequencies.
  double relative_rms = 0.0;
  /// max_k |α(D_k) − α(G_k)|, α = 1 − |(1 − y)/(1 + y)|² (normal incidence).
  double max_abs_delta_alpha = 0.0;
};

/// Thresholds above which a fit is reported as poor. Noise σ per component on admittances of
/// magnitude ~0.3–1 leaves a relative residual of about σ√2/rms|y|: 0.15 allows σ ≈ 0.03 on
/// |y| ≈ 0.3, three times the ~0.01 of a good tube measurement. α = 4 Re y/|1 + y|² moves by
/// ∂α/∂Re y ≈ 4 per unit of Re y at small |y|, so σ = 0.01 alone gives σ_α ≈ 0.04 per point and a
/// maximum of ≈ 3σ_α ≈ 0.12 over a few hundred points (0.11 on samples/reference with its true
/// order): 0.2 flags only what such noise cannot produce.
inline constexpr double kPoorRelativeRms = 0.15;
inline constexpr double kPoorDeltaAlpha = 0.2;

/// Goodness of fit of `model` (at its maximum-likelihood point) to `data`.
GoodnessOfFit goodness_of_fit(const Measurement& data, const ModelResult& model);

/// A warning naming the order, both figures and their thresholds when either is exceeded.
std::optional<std::string> poor_fit_warning(const std::string& order, const GoodnessOfFit& g);

}  // namespace admitgen

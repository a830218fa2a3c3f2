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

/// Thresholds above which a fit is reported as poor. A measurement with noise σ per component on
/// admittances of magnitude ~0.3–1 leaves a relative residual of about σ√2/|y|: 0.15 allows σ ≈ 0.03
/// on |y| ≈ 0.3, far above the ~0.01 of a good tube measurement; |Δα| = 0.1 is the absorption
/// accuracy room-acoustic use needs (one class in EN ISO 11654 spans 0.1–0.2).
inline constexpr double kPoorRelativeRms = 0.15;
inline constexpr double kPoorDeltaAlpha = 0.1;

/// Goodness of fit of `model` (at its maximum-likelihood point) to `data`.
GoodnessOfFit goodness_of_fit(const Measurement& data, const ModelResult& model);

/// A warning naming the order, both figures and their thresholds when either is exceeded.
std::optional<std::string> poor_fit_warning(const std::string& order, const GoodnessOfFit& g);

}  // namespace admitgen

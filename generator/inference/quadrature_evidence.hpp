// SPDX-License-Identifier: MIT
/// @file
/// The evidence of a model with no or one parameter by quadrature, for candidates too cheap to be worth
/// nested sampling (docs/method.md, "Evidence by quadrature"). With θ = T(u), u ∈ [0, 1] (the model's
/// prior transform, so any prior shape), Z = ∫₀¹ L(T(u)) du.
///
/// Method (one parameter):
///  1. scan ln L at kScanPoints + 1 equally spaced u (endpoints included);
///  2. each local maximum of the scan (the 16 highest) is refined by golden-section search between its
///     neighbours; of those within kModeWindow nats of the best refined one, the width d (the distance
///     at which ln L has dropped by 2 nats, about 2σ for a Gaussian peak) is found on each side by
///     bisection in ln d;
///  3. breakpoints u* − 4d, u* − d, u*, u* + d, u* + 4d of every mode split [0, 1] into panels, each
///     integrated by the 15-point Gauss-Kronrod rule with its embedded 7-point Gauss rule;
///  4. while Σ|K₁₅ − G₇| > tolerance · Σ K₁₅, the panel with the largest |K₁₅ − G₇| is halved
///     (at most max_calls evaluations in all).
/// The error estimate |K₁₅ − G₇| is that of the Gauss rule, far larger than the Kronrod rule's own
/// error for a smooth integrand; it is reported as log_z_error (nats, relative error of Z).
/// Assumption, stated: ln L varies smoothly on the scale of the scan (kScanPoints cells over the prior),
/// so every mode of L shows as a local maximum of the scanned ln L. This holds for the effects of
/// diagnosis/effect_candidates.hpp, whose parameters change y smoothly over their priors; a mode
/// narrower than a scan cell *and* off every scanned maximum would be missed.
///
/// The result has the shape of a nested-sampling run (inference/nested_sampler.hpp): the Kronrod nodes
/// as points with log_weight = ln(w_k · h) + ln L_k, so posterior summaries (inference/posterior.hpp)
/// read it unchanged, plus one point of zero weight at the refined maximum (max_likelihood_index finds
/// it). stopped_by is "quadrature" ("analytic" with no parameter: Z = L).
#pragma once

#include "inference/model.hpp"
#include "inference/nested_sampler.hpp"

namespace admitgen {

struct QuadratureSettings {
  double tolerance = 1e-6;  ///< target relative error of Z (so about 1e-6 nats in ln Z)
  long max_calls = 20000;   ///< likelihood evaluations at most; the reported error says what was reached
};

inline constexpr int kScanPoints = 128;
inline constexpr double kModeWindow = 50.0;  ///< nats below the best maximum that a mode may lie (e^{−50}: no mass)

/// Z of a model with dim() ≤ 1 (ENSURE).
NestedRun evidence_by_quadrature(const Model& model, const QuadratureSettings& settings = {});

}  // namespace admitgen

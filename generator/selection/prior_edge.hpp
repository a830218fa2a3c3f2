// SPDX-License-Identifier: MIT
/// @file
/// Parameters whose posterior lies against a bound of its prior range: there the prior, not the data,
/// decides the value, and the evidence of the order depends on where the range was cut (docs/method.md,
/// "Priors").
#pragma once

#include "inference/priors.hpp"
#include "selection/fit.hpp"

#include <optional>
#include <string>

namespace admitgen {

/// A posterior is "against" a bound when it is concentrated (std ≤ kPriorEdgeConcentration × the range's
/// width) and its 95 % interval reaches within kPriorEdgeReach × the width of that bound. The lower bounds
/// at 0 of λ and α (causality) and of β (the symmetry fold) are physical limits, not cuts, and are skipped.
inline constexpr double kPriorEdgeConcentration = 0.05;
inline constexpr double kPriorEdgeReach = 0.01;
/// Under the Gaussian residue prior a residue whose posterior mean lies beyond this many prior standard deviations
/// is held back by the prior (the probability of such a draw is 6e-5).
inline constexpr double kPriorTailSds = 4.0;

/// One warning naming every parameter of `model` against a bound of `priors` (bound and 95 % interval) and
/// the setting that widens the ranges; none when no posterior lies against a cut bound.
std::optional<std::string> prior_edge_warning(const ModelResult& model, const PriorRanges& priors);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// A parameter of the verdict's explanation whose posterior presses on a bound of its prior
/// (docs/diagnosis.md, "A parameter at its prior's bound"): the bound, not the data, then set its value,
/// and the effect is larger than the prior allows or stands in for something outside the vocabulary.
///
///   In the prior's unit coordinate u (u = (θ − lo)/(hi − lo), or ln(θ/lo)/ln(hi/lo) for a log-uniform
///   prior), the posterior presses on the upper bound when its mean lies in the outermost
///   kBoundMeanShare of the range (u ≥ 1 − kBoundMeanShare) and its 95 % interval reaches the outermost
///   kBoundIntervalShare (u(ci95_hi) ≥ 1 − kBoundIntervalShare); on the lower bound likewise.
///
/// A bound that is a physical limit and not a range is not reported: 0 of a non-negative parameter
/// (fractional_order's c₊ and c₋, heteroscedastic_noise's scale: a uniform prior [0, hi]) and a catalogue
/// ratio narrowed to keep its layer physical (porosity ≤ 1, tortuosity ≥ 1: physics/material_spec.hpp).
#pragma once

#include "diagnosis/effect_candidates.hpp"
#include "diagnosis/explanation.hpp"

#include <string>
#include <vector>

namespace admitgen::diagnosis {

/// The mean in the outermost 5 % of the prior's range, and the 95 % interval reaching its outermost 1 %.
inline constexpr double kBoundMeanShare = 0.05;
inline constexpr double kBoundIntervalShare = 0.01;

struct PriorBoundHit {
  std::string effect;     ///< the member's documented name ("material" for a catalogue parameter)
  std::string parameter;  ///< the parameter's name (a material member's "<layer>.<key>")
  bool upper = true;      ///< the upper bound (else the lower)
  double bound = 0.0;     ///< the bound's value
  double mean = 0.0;      ///< the posterior mean of the joint fit
  std::string fix;        ///< what to do about it, in words
};

/// The parameters of the explanation's members that press on a prior bound (rule above), in member order.
std::vector<PriorBoundHit> prior_bound_hits(const Explanation& explanation, const std::vector<EffectCandidate>& candidates);

/// "mic_mismatch gain = 0.09997 at the upper bound 0.1 of its prior: …" (one hit, for the terminal).
std::string prior_bound_text(const PriorBoundHit& hit);

}  // namespace admitgen::diagnosis

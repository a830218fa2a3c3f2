// SPDX-License-Identifier: MIT
/// @file
/// Which unmodelled effect explains the gap: for every candidate e (effect_candidates.hpp) the
/// evidence Z_e = ∫ L(ϑ) π(ϑ) dϑ of "simulated side + e" is computed with the nested sampler of `fit`
/// (inference/nested_sampler.hpp) and compared with the no-effect model, whose evidence is its
/// likelihood (no free parameter):  BF_e = 10 log₁₀(Z_e/Z₀) deciban. The prior volume of ϑ makes the
/// comparison fair between effects with 0 to 3 parameters (Occam factor), so a flexible effect that
/// only fits noise loses against none.
///
/// Each effect then reports its posterior (mean, std, 95 % interval, max-likelihood value) and the gap
/// left at the max-likelihood ϑ: gap_after, shrink = gap_before/gap_after over the whole data, and the
/// band-resolved gap after.
#pragma once

#include "diagnosis/effect_candidates.hpp"
#include "diagnosis/gap_metrics.hpp"
#include "inference/posterior.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace admitgen::diagnosis {

/// Sampler settings. Effects have 0-3 parameters on a fixed simulated admittance, so a hundred live
/// points already give ln Z to ±√(H/n) ≈ 0.4 nat (2 dB), far inside the 20 dB decision margin.
struct IdentificationSettings {
  int live = 100;
  double dlogz = 0.1;
  std::uint64_t seed = 1;  ///< effect i samples with derive_seed(seed, i)
};

struct EffectResult {
  std::string name;
  std::vector<ParameterPrior> priors;
  std::vector<ParameterSummary> parameters;           ///< one per prior, in its order
  std::vector<std::pair<std::string, double>> fixed;  ///< parameters held fixed
  double log_z = 0.0;
  double log_z_error = 0.0;
  double max_log_likelihood = 0.0;
  double bayes_factor_deciban = 0.0;  ///< against no effect
  long calls = 0;
  Gap gap_after;
  double shrink = 1.0;         ///< gap_before.total / gap_after.total
  double explained = 0.0;      ///< fraction of the squared gap explained: 1 − 1/shrink²
  std::size_t band = 0;        ///< index of the band this effect explains most (gap_metrics most_improved_band)
};

struct Identification {
  double log_z_none = 0.0;
  std::vector<EffectResult> effects;  ///< best (largest Bayes factor) first; ties keep the candidate order
};

/// Runs every candidate against y_real (at f_hz, level ‖y_real‖) and ranks them; y_sim is the
/// no-effect model.
Identification identify_effects(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real,
                                const Eigen::ArrayXcd& y_sim, const Gap& gap_before,
                                const std::vector<EffectCandidate>& candidates, const IdentificationSettings& settings);

}  // namespace admitgen::diagnosis

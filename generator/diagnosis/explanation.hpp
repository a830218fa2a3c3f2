// SPDX-License-Identifier: MIT
/// @file
/// Combined explanations (docs/diagnosis.md, "Combined explanations"): real gaps are rarely one effect.
/// After the single effects (effect_identification.hpp), a greedy forward selection by evidence:
///
///   E₁ = the single effect with the largest evidence, if BF(E₁ : none) ≥ 20 dB (else no explanation);
///   round r: for every candidate e not in E_r, the evidence of E_r + e with all its parameters free
///   (fitted jointly, combine_effects); the best is accepted if BF(E_r + e : E_r) ≥ 20 dB;
///   stop when no addition is decisive, when the residual of E_r is white (residual_whiteness.hpp), or at
///   kMaxExplanationEffects members. A white residual has no structure left in its mean, but a noise
///   shape (heteroscedastic_noise) does not show in the lag-1 test: with a white residual the round
///   still tries the noise-stage effects, and only them.
///   swap step: after an addition that leaves the residual structured, every earlier member in turn is
///   replaced by every candidate not in the explanation (all refitted jointly); the best swap is kept if
///   it is decisive (≥ 20 dB) against the explanation as it stands, at most one per round. It undoes a
///   first member that mimics two true ones, which pure addition cannot.
///
/// Each effect enters at most once (each catalogue parameter of `material` counts as its own effect).
/// The evidence of a joint model pays the Occam factor of every added parameter, so an addition that
/// only fits noise is not decisive. Every joint candidate samples from reference densities on its prior
/// built on earlier posteriors (its members' in the explanation, the added member's single-effect one),
/// the likelihood divided by them: the same evidence in fewer calls (docs/method.md, "Reference priors in
/// the combined search"). Round r samples on the seed streams r·n + i (n candidates), after
/// the single effects' 0 … n − 1, the swaps after round r on kMax·n·r + i and the steps restated after a
/// swap on kMax·n·r + (kMax − 1)·n + i, so the search is deterministic whatever the thread count.
#pragma once

#include "diagnosis/effect_identification.hpp"

#include <cstddef>
#include <vector>

namespace admitgen::diagnosis {

/// Members at most (bounds the search's cost; a gap that needs more is reported as it stands).
inline constexpr std::size_t kMaxExplanationEffects = 3;

struct ExplanationStep {
  std::size_t candidate = 0;          ///< index into the candidates
  /// Of the first k + 1 members against the first k (this member is the k-th, from 0), each fitted jointly.
  double bayes_factor_deciban = 0.0;
  double shrink_added = 1.0;  ///< gap of the first k members / gap of the first k + 1
};

struct Explanation {
  std::vector<ExplanationStep> steps;  ///< in the order accepted; empty when no single effect is decisive
  /// The accepted members fitted jointly; priors and parameters concatenated in step order (gap fields
  /// and Bayes factor against no effect filled). Meaningless when steps is empty.
  EffectResult joint;
  /// Every joint candidate each round evaluated, in candidate order (costs for benchmarks; not written).
  std::vector<std::vector<EffectResult>> rounds;
  /// The parameter summaries of member k: joint.parameters[offset(k) …].
  std::vector<ParameterSummary> member_parameters(std::size_t k, const std::vector<EffectCandidate>& candidates) const;
};

/// The search above, from the single effects of identify_effects (same candidates, f_hz and y_real).
Explanation explain(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real, const Gap& gap_before,
                    const std::vector<EffectCandidate>& candidates, const Identification& identification,
                    const IdentificationSettings& settings, Progress& progress);

}  // namespace admitgen::diagnosis

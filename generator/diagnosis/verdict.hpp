// SPDX-License-Identifier: MIT
/// @file
/// The decision rule of `diagnose`, stated once:
///
///   Let e* be the effect with the largest Bayes factor BF against no effect (effect_identification).
///   The verdict is e* if BF(e*) ≥ 20 deciban (odds ≥ 100 : 1, "decisive" on Jeffreys' scale);
///   otherwise it is `none`.
///
/// The band of the verdict is the band e* explains most (largest drop of g_b²); for `none` it is the
/// worst band of the gap. shrink = gap before / gap after over the whole data (1 for `none`).
/// Decisive support does not mean the effect is the whole story: on real data the residual is rarely
/// white, so an effect can be decisively better than none and still explain little; `explained` and
/// `white_after` say how much is left.
/// The runner-up's margin is reported as well: two effects within a few deciban of each other are
/// near-degenerate on these data (e.g. reference_plane and temperature both give a phase error ∝ f),
/// which the report then says.
#pragma once

#include "diagnosis/effect_identification.hpp"
#include "diagnosis/gap_metrics.hpp"

#include <string>

namespace admitgen::diagnosis {

inline constexpr double kDecisiveDeciban = 20.0;

struct Verdict {
  std::string effect = "none";
  double bayes_factor_deciban = 0.0;  ///< of e* (also when the verdict is none)
  double margin_deciban = 0.0;        ///< BF(e*) − BF(runner-up); +inf when there is no runner-up
  double shrink = 1.0;
  double explained = 0.0;  ///< 1 − 1/shrink²: < 0.5 means the effect is real but most of the gap is not it
  ThirdOctaveBand band;
  bool white_after = false;  ///< is the residual after the verdict white (residual_whiteness)?
};

/// Applies the rule above.
Verdict decide(const Gap& gap, const Identification& identification);

/// The rule in words, written to diagnosis.json.
std::string describe_decision_rule();

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
#include "diagnosis/verdict.hpp"

#include <fmt/format.h>

#include <limits>

namespace admitgen::diagnosis {

Verdict decide(const Gap& gap, const Identification& id) {
  Verdict v;
  v.band = gap.bands[gap.worst].band;
  v.white_after = gap.whiteness.white;
  if (id.effects.empty()) return v;
  const EffectResult& best = id.effects.front();
  v.bayes_factor_deciban = best.bayes_factor_deciban;
  v.margin_deciban = id.effects.size() > 1 ? best.bayes_factor_deciban - id.effects[1].bayes_factor_deciban
                                           : std::numeric_limits<double>::infinity();
  if (best.bayes_factor_deciban < kDecisiveDeciban) return v;
  v.effect = best.name;
  v.shrink = best.shrink;
  v.explained = best.explained;
  v.band = gap.bands[best.band].band;
  v.white_after = best.gap_after.whiteness.white;
  return v;
}

std::string describe_decision_rule() {
  return fmt::format(
      "the effect with the largest Bayes factor against no effect, if that factor is at least {:g} deciban "
      "(odds 100:1); otherwise none",
      kDecisiveDeciban);
}

}  // namespace admitgen::diagnosis

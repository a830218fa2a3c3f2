// SPDX-License-Identifier: MIT
#include "selection/prior_edge.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

namespace admitgen {

std::optional<std::string> prior_edge_warning(const ModelResult& model, const PriorRanges& priors) {
  std::vector<std::string> against;
  const std::vector<Family> families = model.order.families();
  for (std::size_t k = 0; k < model.parameters.size() && k < families.size(); ++k) {
    const ParameterSummary& p = model.parameters[k];
    const Family f = families[k];
    const Range& r = priors.of(f);
    const double width = r.width();
    if (!(p.std <= kPriorEdgeConcentration * width)) continue;  // spread over the range: unconstrained, not cut
    const bool physical_lo = r.lo <= 0.0 && (f == Family::lambda || f == Family::alpha || f == Family::beta);
    const bool at_lo = !physical_lo && p.ci95_lo - r.lo <= kPriorEdgeReach * width;
    const bool at_hi = r.hi - p.ci95_hi <= kPriorEdgeReach * width;
    if (at_lo || at_hi)
      against.push_back(fmt::format("{} at {:.6g} (95 % interval [{:.6g}, {:.6g}])", p.name, at_lo ? r.lo : r.hi,
                                    p.ci95_lo, p.ci95_hi));
  }
  if (against.empty()) return std::nullopt;
  return fmt::format(
      "{}: posterior against its prior bounds: {}; the ranges, not the data, set these values, and the evidence of {} "
      "depends on where they were cut; if such values are physical, widen the ranges with {}, otherwise check how "
      "the data were read",
      model.order.name(), fmt::join(against, ", "), model.order.name(), setting("priors"));
}

}  // namespace admitgen

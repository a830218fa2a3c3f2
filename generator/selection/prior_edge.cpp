// SPDX-License-Identifier: MIT
#include "selection/prior_edge.hpp"

#include "core/errors.hpp"
#include "inference/pole_space.hpp"
#include "model/residue_basis.hpp"
#include "passivity/passive_estimate.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

namespace admitgen {

namespace {

/// Under the Gaussian residue prior: the residues whose posterior mean lies beyond kPriorTailSds prior standard
/// deviations (at the posterior mean of the poles): the admittance scale, not the data, holds them back.
std::vector<std::string> residues_in_prior_tail(const ModelResult& model, const PriorRanges& priors) {
  const Order& o = model.order;
  if (model.parameters.size() != static_cast<std::size_t>(o.dim())) return {};
  std::vector<double> poles;
  for (int i : pole_indices(o)) poles.push_back(model.parameters[static_cast<std::size_t>(i)].mean);
  const std::vector<int> at = residue_indices(o);
  std::vector<double> sd(at.size());
  gaussian_residue_scales(o, poles.data(), priors.admittance_scale, sd.data());
  std::vector<std::string> out;
  for (std::size_t k = 0; k < at.size(); ++k) {
    const ParameterSummary& p = model.parameters[static_cast<std::size_t>(at[k])];
    if (std::abs(p.mean) > kPriorTailSds * sd[k])
      out.push_back(fmt::format("{} = {:.6g} ({:.1f} prior standard deviations)", p.name, p.mean, std::abs(p.mean) / sd[k]));
  }
  return out;
}

/// The warning for residues in the prior's tail. Where the data's passive bound (docs/passivity.md, "The passive
/// bound") lies far above the best sample's fit, what the tail values buy is Re G < 0: a larger scale would only
/// admit more of it, so the advice is to check the measurement.
std::string tail_warning(const ModelResult& model, const PriorRanges& priors, const std::vector<std::string>& tail) {
  const std::string head = fmt::format(
      "{}: residues far in the tail of their Gaussian prior: {}; the admittance scale {} holds them back and sets the "
      "evidence of {}",
      model.order.name(), fmt::join(tail, ", "), priors.admittance_scale, model.order.name());
  const auto& e = model.passive;
  if (e.passive_bound_relative_rms_residual &&
      passivity::at_passive_bound(e.relative_rms_residual, *e.passive_bound_relative_rms_residual))
    return fmt::format("{}; they are not physical: no passive admittance found fits these data better than {:.3g} % "
                       "(the passive bound) where the best sample reaches {:.3g} %, so the tail values buy a fit with "
                       "Re G < 0; check the measurement rather than raise {}",
                       head, 100.0 * *e.passive_bound_relative_rms_residual,
                       100.0 * e.best_sample_relative_rms_residual, setting("admittance_scale"));
  return fmt::format("{}; if such values are physical, raise it with {}", head, setting("admittance_scale"));
}

}  // namespace

std::optional<std::string> prior_edge_warning(const ModelResult& model, const PriorRanges& priors) {
  if (priors.residues == ResiduePrior::gaussian) {
    const std::vector<std::string> tail = residues_in_prior_tail(model, priors);
    if (!tail.empty()) return tail_warning(model, priors, tail);
  }
  std::vector<std::string> against;
  const std::vector<Family> families = model.order.families();
  for (std::size_t k = 0; k < model.parameters.size() && k < families.size(); ++k) {
    const ParameterSummary& p = model.parameters[k];
    const Family f = families[k];
    if (priors.residues == ResiduePrior::gaussian && is_residue(f)) continue;  // unbounded
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

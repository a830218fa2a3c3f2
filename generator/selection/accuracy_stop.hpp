// SPDX-License-Identifier: MIT
/// @file
/// Where the accuracy target stops a fit (docs/method.md, "Accuracy target"): each order's passive estimate and
/// its accuracy, which orders a rule may choose, and what the fit says when the target is met while the evidence
/// would still rise (a note), or cannot be met (a warning naming the band and what the data hold there).
#pragma once

#include "data/measurement.hpp"
#include "passivity/passive_estimate.hpp"
#include "selection/fit.hpp"

#include <string>
#include <vector>

namespace admitgen {

/// Sets `passive` and `accuracy` of every model that has no accuracy yet (one task per order: the same bits at
/// any thread count, docs/method.md, "Determinism").
void estimate_passive(const Measurement& data, const FitSettings& settings, std::vector<ModelResult>& models,
                      const passivity::LazyPassiveBound& bound);

/// The selection rule over `models`, among the usable orders: within settings.max_buffers and with determined
/// evidence (independent runs that agree, RerunCheck::kMaxGapNats). Models without accuracy count as missing the
/// target. When no order is usable (every order's runs disagree) the budget alone decides which may be chosen.
std::size_t select_usable(const FitSettings& settings, const std::vector<ModelResult>& models);

/// The note of a met target while the evidence would rise further (empty when it would not): `would_grow` says
/// that growth would have added orders around the selection. For a missed target, a note only when growth stopped
/// because the target is out of reach (target_out_of_reach) while the evidence would still have grown.
std::string target_met_note(const Measurement& data, const FitSettings& settings, const std::vector<ModelResult>& models,
                            std::size_t selected, bool would_grow);

/// Why more poles cannot bring the selected order's passive estimate to the target, or empty when they might (or
/// it meets the target, or there is none): its residual is the data's noise; or passivity costs its estimate more
/// than PassiveEstimate::kCostRatio and the closest passive admittance of any order (`bound`) misses the target
/// too; or it misses only at a spike narrower than any pole pair the data resolve. Growth stops there
/// (grid_growth.hpp).
std::string target_out_of_reach(const Measurement& data, const FitSettings& settings, const ModelResult& selected,
                                const passivity::LazyPassiveBound& bound);

/// The warning of a target no fitted order meets, naming the selected order's worst band and the feature there.
std::string target_missed_warning(const Measurement& data, const FitSettings& settings,
                                  const std::vector<ModelResult>& models, std::size_t selected,
                                  const passivity::LazyPassiveBound& bound);

}  // namespace admitgen

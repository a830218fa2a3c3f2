// SPDX-License-Identifier: MIT
/// @file
/// The missed-mode checks of a fit's runs (declared with MissedMode in selection/fit.hpp, defined in
/// missed_modes.cpp) and the two judgements the re-runs, the warnings and the selection share
/// (docs/method.md, "Model selection").
#pragma once

#include "selection/fit.hpp"
#include "selection/order_marginals.hpp"

namespace admitgen {

/// Both checks of MissedMode (selection/fit.hpp); the second needs the data and the priors (skipped for `passive`
/// fits, whose likelihood also needs the reduced model passive). Runs of the pole sampler are compared on their
/// marginals, taken from `marginals` (built once per order for the whole fit).
std::vector<MissedMode> missed_modes(const Measurement& data, const FitSettings& settings,
                                     const std::vector<ModelResult>& models, OrderMarginals& marginals,
                                     double tolerance = 2.0);

/// Whether an order's independent runs disagree by more than the largest gap a note explains (its error, from
/// their scatter, above RerunCheck::kMaxGapNats): one found evidence another missed, and its ln Z is undetermined.
/// Where the fit asked for independent runs (FitSettings::runs ≥ 2), re-run rounds treat it as a missed mode and
/// the fit warns if it stays (runs_disagree_warnings); no selection rule chooses it (selection/accuracy_stop.hpp).
bool runs_disagree(const ModelResult& m);

/// Whether the missed mode `m` is explained by the order's last re-run round (RerunCheck): ln Z agreed and the gap
/// is small.
bool settled(const ModelResult& run, const MissedMode& m);

}  // namespace admitgen

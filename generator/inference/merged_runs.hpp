// SPDX-License-Identifier: MIT
/// @file
/// Independent nested-sampling runs of one model merged into one run (docs/method.md, "Missed modes"): a
/// re-run with k times the live points is made as k runs of the usual live points on their own seed streams,
/// which run in parallel, instead of one run that only one thread can make.
///
/// Each run's Z_j is an unbiased estimate of Z (Skilling 2006, §4), so their mean is one; its error is each
/// run's error weighted by its share of Σ Z_j, √(Σ (Z_j/ΣZ)² δ_j²) (δ_j/√k for k alike runs, as for one run of
/// k·n live points, whose error is √(H/kn)). The posterior is the mixture of the runs' posteriors in proportion
/// to their evidences: each point keeps its weight L_i ΔX_i, divided by k. A run that missed a mode the other
/// found thus gives way to it in the posterior, and Z is the mean of a low and a right estimate, as a single
/// run that found the mode with half of its points would have it.
#pragma once

#include "inference/nested_sampler.hpp"

#include <vector>

namespace admitgen {

/// Merges `runs` (at least one, all of one model, each with `live` live points). Rows: every run's points
/// but its final `live`, in ascending ln L, then the final `live` of every run, in ascending ln L, so that the
/// last k·live rows are where the runs ended, as the last `live` rows of one run are. One run is returned as it is.
NestedRun merge_runs(const std::vector<NestedRun>& runs, int live);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Runs of one model made with independent seeds, merged into one run as if made with the sum of their live
/// points (docs/method.md, "Merged runs").
///
/// A run of n live points is n threads, each a sequence of points of rising likelihood (Higson et al. 2019,
/// "Dynamic nested sampling", Stat. Comput. 29, §2); the threads of independent runs of one model together
/// are a run whose number of live points at each death is the number of threads alive there. Sorting the
/// points of every run by the likelihood they were sampled under, the merged live count at a point is the
/// sum of each run's count there: n_k below the run's last death, then n_k − j after its j-th final live
/// point (the final live points close the run one at a time). The prior volume then shrinks by e^{−1/n_i}
/// at point i (Skilling 2006, §3), point i weighs L_i (X_{i−1} − X_i), and ln Z has the error √(H/Σ n_k).
/// Runs can scatter more than that error says (Var ln Z_k = c/n_k with c > H: replacements that stay in their
/// mode let the live points' share of the modes drift, which H does not see); scatter_error measures it.
#pragma once

#include "inference/nested_sampler.hpp"

#include <vector>

namespace admitgen {

/// One run to merge and the live points it was made with.
struct RunPart {
  const NestedRun* run;
  int live;
};

/// The merged run. Each part's points are its deaths (the first `iterations`) and then its final live points
/// in ascending likelihood (run_nested_sampling's order); points of zero weight after them (a pole run's best
/// fit, inference/poles_sampler.hpp) follow the merged points with zero weight. The likelihood that orders
/// the points is NestedRun::sampled_log_likelihood where a part has it, else log_likelihood; the parts must
/// agree on which. Ties are broken by part, then by position. calls and iterations are the parts' sums,
/// stopped_by the first part's, the support fraction the live-weighted mean of theirs.
NestedRun merge_runs(const std::vector<RunPart>& parts);

/// The error of the merged ln Z from the runs' own scatter, √(ĉ/Σ n_k) with ĉ = Σ n_k (ln Z_k − μ)² / (m − 1)
/// the unbiased estimate of c (μ the live-weighted mean of the m runs' ln Z); 0 for one run.
double scatter_error(const std::vector<RunPart>& parts);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Nested sampling over the poles only, the residues and the noise integrated out exactly under the
/// Gaussian residue prior (inference/residue_evidence.hpp; docs/method.md, "Sampling the poles only"), then
/// the complete posterior: for every pole sample, σ and the residues drawn exactly from their conditional,
/// so the returned run looks like a full-θ run (same packing, same weights semantics) to summaries,
/// predictive bands, reports and emit.
#pragma once

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/priors.hpp"
#include "model/order.hpp"

namespace admitgen {

/// Runs the pole sampler for `order` under `priors` (whose residues must be ResiduePrior::gaussian).
/// Full θ per point (model/order.hpp packing), weights of the pole run; log_likelihood holds the full
/// ln L(θ) of each stored θ. One extra point of zero weight (log_weight = −∞) ends the run: the poles of
/// the highest marginal likelihood with their least-squares residues, so max_likelihood_index finds the
/// best θ the run saw. calls, iterations, information, ln Z and its error are those of the pole run. With
/// no poles (Q0S0) the evidence is the closed form itself (stopped_by "analytic", error 0) and
/// `settings.live` draws of r form the posterior. `draw_seed` seeds the residue draws.
NestedRun run_poles_sampler(const Measurement& data, const Order& order, const PriorRanges& priors,
                            bool reduce_symmetry, DataCount count, const NestedSettings& settings,
                            std::uint64_t draw_seed, const NestedProgressFn& progress = {});

/// Points of a run whose posterior share is below this over the number of points keep their least-squares
/// residues instead of a draw from the conditional (together at most this share of the posterior).
constexpr double kNegligibleShare = 1e-6;

}  // namespace admitgen

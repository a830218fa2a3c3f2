// SPDX-License-Identifier: MIT
/// @file
/// A larger order's best model read as a smaller one (docs/method.md, "Model selection", missed modes).
///
/// If (Q, S) is contained in (Q', S'), dropping Q' − Q real poles and S' − S pairs of a θ' of the larger
/// order leaves poles of the smaller one; with the residues refitted to the data over the residue box (the
/// prior's support), that is a point of the smaller order's parameter space whose likelihood its own run
/// should have reached. Where the larger order's best θ', so reduced, beats the smaller order's best ln L,
/// the smaller order's run missed the mode that the larger one found (its evidence is underestimated),
/// the mirror image of the check by contained orders (selection/fit.hpp missed_modes).
#pragma once

#include <cstddef>
#include <limits>

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/nested_sampler.hpp"
#include "inference/priors.hpp"
#include "inference/residue_evidence.hpp"
#include "model/order.hpp"

namespace admitgen {

/// The highest ln L of `small` over every way of dropping surplus terms of θ' (order `big`, which must
/// contain `small`; θ' packed as model/order.hpp), the kept poles as they are and the residues (G∞
/// included) the least-squares fit, over the residue box under the uniform prior of `priors`
/// (inference/box_least_squares.hpp), unbounded under the Gaussian prior.
/// With small = big, θ' with its residues refitted: the like-for-like reference for a run's own best
/// (a sampled θ' need not hold the best residues of its poles). −∞ when no reduction gives a usable basis
/// (numerically singular).
double reduced_log_likelihood(const Measurement& data, const Order& small, const Order& big, const double* theta_big,
                              const PriorRanges& priors, DataCount count);

/// The same comparisons for runs of the pole sampler, made on the function it samples: the marginal
/// likelihood L(ψ) of the poles, residues and noise integrated out under the Gaussian residue prior
/// (inference/residue_evidence.hpp). The profile ln L of the functions above is no fair yardstick there:
/// a spare pole can fit noise with large residues that the prior shrinks, so the marginal's peak, where the
/// run ends, need not be the best fit, and the best fit among the samples is an extreme of a few lucky ones.
/// Nested sampling ends at the peak of what it samples, so a point of higher marginal is a mode it missed.
struct MarginalPeak {
  std::size_t row = 0;  ///< the run's sample (θ packed as model/order.hpp) at the peak
  double log_l = -std::numeric_limits<double>::infinity();  ///< ln L(ψ) there
};
/// The highest marginal over a run's final `live` points and anything after them (where nested sampling
/// ends), read from NestedRun::sampled_log_likelihood where the run holds it (then over all its points);
/// log_l = −∞ for an empty run.
/// `evidence` is the marginal of `order` on the data (built once per order by the caller and passed to all
/// three functions: its construction is most of the cost of a check).
MarginalPeak marginal_peak(const ResidueEvidence& evidence, const Order& order, const NestedRun& run, int live);
/// The highest marginal of `small` (its marginal `small_evidence`) over every way of dropping surplus poles of θ'
/// (order `big`).
double reduced_log_marginal(const ResidueEvidence& small_evidence, const Order& small, const Order& big,
                            const double* theta_big);
/// The highest marginal of `big` over every way of completing the poles of θ (order `small`) with surplus
/// poles of θ' (order `big`): where the larger run's own peak is below it, the larger run missed the mode
/// that the smaller one found. `big_evidence`: the marginal of `big`.
double completed_log_marginal(const ResidueEvidence& big_evidence, const Order& small, const double* theta_small,
                              const Order& big, const double* theta_big);

}  // namespace admitgen

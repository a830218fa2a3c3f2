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

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/priors.hpp"
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

}  // namespace admitgen

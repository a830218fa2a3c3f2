/// @file
/// The Student-t pieces the residue marginalisation needs (docs/method.md, "Residues given the
/// poles"): tails of the univariate t, chi-square draws, and draws of a univariate t truncated to an
/// interval. Distribution functions come from Boost.Math; every random draw goes through core/rng.hpp,
/// so a seed gives the same draws on every platform.
#pragma once

#include "core/rng.hpp"

namespace admitgen {

/// Upper tail P(T > z) of the standard Student t with ν degrees of freedom. Tails below 1e-300 are 0.
double student_t_upper_tail(double nu, double z);

/// Standard t value z with P(T > z) = 1e-16 for ν degrees of freedom: beyond it a tail is below any
/// mass this code resolves, and student_t_upper_tail need not be called (it is the cost of a call).
double student_t_negligible_tail(double nu);

/// A chi-square draw with ν degrees of freedom: 2·Gamma(ν/2), Gamma by Marsaglia & Tsang (2000),
/// exact rejection (shape a < 1 as Gamma(a + 1)·U^{1/a}).
double chi_square_draw(double nu, Rng& rng);

/// A standard t (ν degrees of freedom) draw conditioned on a ≤ T ≤ b, by inversion of the CDF on the
/// side of the interval with the larger tail-free precision (the interval is mirrored to the left of
/// 0 when it lies right of it, so probabilities near 1 are never subtracted).
double truncated_student_t_draw(double nu, double a, double b, Rng& rng);

}  // namespace admitgen

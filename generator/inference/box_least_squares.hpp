// SPDX-License-Identifier: MIT
/// @file
/// The minimum of a positive definite quadratic over a box: the least-squares residues inside the uniform prior's
/// box, for the missed-mode check by reduced models under `--prior table1` (selection/reduced_model.hpp;
/// docs/method.md, "Residues given the poles").
///
/// Minimises (x − c)ᵀ M (x − c) over lo ≤ x ≤ hi by a primal active-set method (Nocedal & Wright,
/// Numerical Optimization, 2nd ed., §16.5): from c clamped to the box, each step solves for the free
/// coordinates with the bound ones fixed, walks towards that solution until a bound blocks (the blocking
/// coordinate joins the bound set), and at a stationary point frees the bound coordinate whose
/// multiplier has the wrong sign. The objective never increases and the iterate always lies in the box,
/// so stopping at the iteration cap still returns an admissible point.
///
/// No Debian package offers a bounded least-squares or box-QP solver for C++ (Eigen has none; qpOASES,
/// OSQP and eiquadprog are not packaged), and p ≤ 10 here, so the method is written out. The project's
/// general solver, numerics/least_squares_inequality.hpp (LSI through NNLS, Lawson & Hanson), solves the same
/// problem with G = [I; −I], h = [lo; −hi], but through the dual: its iterates need not lie in the box when
/// it stops early.
#pragma once

#include <Eigen/Core>

namespace admitgen {

/// x* = argmin_{lo ≤ x ≤ hi} (x − c)ᵀ M (x − c), M symmetric positive definite (p × p, p small). Returns
/// a point of the box; `iterations` (if not null) receives the steps taken, `converged` whether the KKT
/// conditions hold (multipliers of bound coordinates with the right sign, relative tolerance 1e-12).
Eigen::VectorXd box_least_squares(const Eigen::MatrixXd& m, const Eigen::VectorXd& c, const Eigen::VectorXd& lo,
                                  const Eigen::VectorXd& hi, bool* converged = nullptr, int max_iterations = 0);

}  // namespace admitgen

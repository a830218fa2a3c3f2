// SPDX-License-Identifier: MIT
/// @file
/// Linear least squares with linear inequality constraints (LSI), the small convex QPs that passivity
/// enforcement solves (docs/passivity.md):
///
///   minimise ‖E x − f‖²   subject to   G x ≥ h,
///
/// by the method of Lawson & Hanson, *Solving Least Squares Problems* (1974; SIAM 1995), ch. 23:
/// LSI → least distance programming (LDP, §23.3) → non-negative least squares (NNLS, ch. 23 §3,
/// Algorithm 23.10). E must have full column rank (the residue bases of distinct poles do).
///
/// Debian packages no LSI/QP library with a C/C++ API small enough for this (coinor-clp is an LP/QP
/// simplex for large sparse problems, coinor-ipopt a general NLP solver); the problems here have at most
/// ~20 unknowns and a few hundred constraints, which this direct method solves exactly in microseconds.
/// It is tested against brute-force enumeration of active sets (tests/numerics/).
#pragma once

#include <Eigen/Core>

namespace admitgen::numerics {

/// min ‖A x − b‖ subject to x ≥ 0 (Lawson–Hanson active set). Returns x.
Eigen::VectorXd non_negative_least_squares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

struct LsiSolution {
  bool feasible = false;  ///< false: no x satisfies G x ≥ h (x is then undefined)
  Eigen::VectorXd x;
};

/// min ‖E x − f‖² s.t. G x ≥ h. Columns of E and rows of G are equilibrated internally.
LsiSolution least_squares_inequality(const Eigen::MatrixXd& e, const Eigen::VectorXd& f, const Eigen::MatrixXd& g,
                                     const Eigen::VectorXd& h);

}  // namespace admitgen::numerics

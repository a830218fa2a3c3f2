// SPDX-License-Identifier: MIT
/// @file
/// Real SISO state-space realisations: the container, the realisation of the continuous multipole model,
/// and the bilinear (Möbius) map of a discrete realisation to a continuous one (docs/physics.md §2.3).
/// These are what the exact (Hamiltonian) passivity test (model/passivity.hpp) works on.
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>

namespace admitgen {

/// G(s) = D + C (sI − A)^{-1} B (continuous) or H(z) = D + C (zI − A)^{-1} B (discrete).
struct StateSpace {
  Eigen::MatrixXd A;
  Eigen::VectorXd B;
  Eigen::RowVectorXd C;
  double D = 0.0;
  Eigen::Index states() const { return A.rows(); }
};

/// Continuous realisation of G (θ packed as model/order.hpp), docs/physics.md §2.3(a):
/// real pole A_i = −λ, B_i = 1, C_i = A_q; pair A_i = [−α β; −β −α], B_i = [1 0]ᵀ, C_i = [2B −2C];
/// D = G∞.
StateSpace continuous_realisation(const Order& order, const double* theta);

/// The continuous system G_c(s) = H((1 + s)/(1 − s)) (docs/physics.md §2.3, "Discrete filters"):
/// A_c = (A + I)^{-1}(A − I), B_c = √2 (A + I)^{-1} B, C_c = √2 C (A + I)^{-1}, D_c = D − C (A + I)^{-1} B.
/// Re H(e^{jθ}) = Re G_c(jω) with ω = tan(θ/2). Throws InternalError if A has an eigenvalue at z = −1.
StateSpace bilinear_to_continuous(const StateSpace& discrete);

}  // namespace admitgen

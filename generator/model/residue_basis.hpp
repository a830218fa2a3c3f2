// SPDX-License-Identifier: MIT
/// @file
/// The multipole model is linear in its residues once the poles are fixed (docs/method.md, "Residues
/// given the poles"). With r = (G∞, A_1, …, A_Q, B_1, C_1, …, B_S, C_S) (1 + Q + 2S numbers),
///
///   G(jω) = Σ_k r_k φ_k(ω),   φ_G∞ = 1,   φ_A,q = 1/(λ_q + jω),
///   φ_B,s = 1/(α_s + j(ω + β_s)) + 1/(α_s + j(ω − β_s)),
///   φ_C,s = j/(α_s + j(ω + β_s)) − j/(α_s + j(ω − β_s))
///
/// (Θ/(θ + jω) + Θ*/(θ* + jω) with Θ = B + jC, θ = α + jβ, differentiated by B and by C).
/// Fitting residues to data for given poles, enforcing Re G ≥ 0 on chosen frequencies, and integrating
/// the residues out of the likelihood all work on these basis columns; this file is their one definition.
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen {

/// Basis values at a frequency grid: G = re·r + j im·r (each N × (1 + Q + 2S)).
struct ResidueBasis {
  Eigen::MatrixXd re;
  Eigen::MatrixXd im;
};

/// Number of residue parameters of an order: 1 + Q + 2S.
int residue_count(const Order& order);

/// Indices into θ (model/order.hpp packing) of r, in the order above.
std::vector<int> residue_indices(const Order& order);

/// r taken out of θ / written into θ (poles untouched).
Eigen::VectorXd residues_of(const Order& order, const Eigen::VectorXd& theta);
void set_residues(const Order& order, const Eigen::VectorXd& r, Eigen::VectorXd& theta);

/// The basis at angular frequencies ω (rad/s, ≥ 0) for the poles in θ (its residues are ignored).
/// ω = +∞ is allowed and gives the row of G(j∞) = G∞.
ResidueBasis residue_basis(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega);

/// ∂G(jω)/∂ψ of the full model θ (its residues included) with respect to its poles
/// ψ = (λ_1, …, λ_Q, α_1, β_1, …, α_S, β_S), at angular frequencies ω (rad/s, ≥ 0; +∞ gives a zero row):
///
///   ∂G/∂λ_q = −A_q φ_A,q²,
///   ∂G/∂α_s = −(B_s + jC_s) p² − (B_s − jC_s) m²,   ∂G/∂β_s = −j(B_s + jC_s) p² + j(B_s − jC_s) m²,
///
/// with p = 1/(α_s + j(ω + β_s)), m = 1/(α_s + j(ω − β_s)) (the derivative of each 1/(x + jω) is −1/(x + jω)²).
/// G = re + j im, each N × (Q + 2S), columns in the order of ψ. The Jacobian of the variable-projection refit
/// of the passive estimate (docs/passivity.md, "Passive estimate").
ResidueBasis pole_derivatives(const Order& order, const Eigen::VectorXd& theta, const Eigen::ArrayXd& omega);

}  // namespace admitgen

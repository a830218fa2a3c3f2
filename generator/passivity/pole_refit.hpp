// SPDX-License-Identifier: MIT
/// @file
/// The poles of the passive estimate, searched (docs/passivity.md, "Searching the poles").
///
/// For poles ψ, let r*(ψ) be the residues closest to the target under Re G(jω) ≥ 2δ on the constraint set
/// Ω(ψ) (passivity/passive_residues.hpp: a convex LSI, solved exactly) and
///
///   F(ψ) = Σ_i w_i² |t_i − G(jω_i; ψ, r*(ψ))|²,
///
/// the fit of the best passive model with these poles (variable projection: Golub & Pereyra 1973, SIAM J.
/// Numer. Anal. 10(2), with the residues eliminated by the constrained solve). F is minimised from a start by
/// Levenberg–Marquardt steps (Moré 1978, "The Levenberg–Marquardt algorithm: implementation and theory",
/// Lecture Notes in Math. 630; damping update of Nielsen 1999, IMM-REP-1999-05) on the joint linearisation in
/// (ψ, r), with the constraints linearised too: each step is the LSI
///
///   min_δ ‖J δ − ε‖² + μ‖D δ‖²   s.t.   Re G_j + ∇Re G_j · δ ≥ δ_margin   (ω_j ∈ Ω),
///
/// J = ∂(model)/∂(r, u) (u = ln λ, ln α, β: rates stay positive), ε the residual, D² = diag JᵀJ (kept at its
/// running maximum), and each pole's step bounded (a rate by a factor 10, β by 10× the pair's modulus, so
/// every trial stays finite), within a box where the data inform the poles (λ ≥ ω_min/10, α ≥ the data's
/// smallest frequency spacing, rates and |β| ≤ 10 ω_max; a start outside it keeps its value as the limit).
/// Only the poles of the step are kept; the residues are r*(ψ + δψ), so every point visited
/// is passive on Ω and F never increases. The caller certifies the result for every ω (the Hamiltonian test,
/// in passive_residues).
#pragma once

#include "model/order.hpp"
#include "passivity/passive_residues.hpp"

#include <Eigen/Core>

namespace admitgen::passivity {

struct PoleRefit {
  Eigen::VectorXd theta;          ///< the poles found with their residues r*(ψ) (not yet certified)
  double start_sum_squares = 0;   ///< F at the start's poles
  double sum_squares = 0;         ///< F at theta's poles (≤ start_sum_squares)
  int steps = 0;                  ///< Levenberg–Marquardt steps tried
  int accepted = 0;               ///< of which accepted
};

/// The variable-projection objective F(ψ) and its residues r*(ψ) for the poles of `theta` (residues
/// ignored): the constrained solve on Ω(ψ) at margin 2δ (δ = constraint_margin(target, 1e-9)), no certificate.
struct ProjectedResidues {
  bool feasible = false;
  Eigen::VectorXd theta;     ///< the poles of the input with r*(ψ)
  double sum_squares = 0.0;  ///< F(ψ)
};
ProjectedResidues project_residues(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target);

/// Minimises F from the poles of `start` (its residues are ignored) in at most `max_steps` steps. Pole sets
/// whose residue basis is too ill-conditioned for the constraint solve (nearly coincident poles) are never
/// entered; a start that is one is returned unsearched (accepted = 0, F = +∞).
/// Deterministic: no randomness, a fixed sequence of floating-point operations.
PoleRefit refit_poles(const Order& order, const Eigen::VectorXd& start, const ResidueTarget& target, int max_steps);

/// θ in the reported form (docs/formats.md): β_s ≥ 0 (the pair (β, C) → (−β, −C) is the same term), real
/// poles by λ and pairs by β ascending. G is unchanged.
Eigen::VectorXd canonical_terms(const Order& order, const Eigen::VectorXd& theta);

}  // namespace admitgen::passivity

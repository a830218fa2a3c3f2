// SPDX-License-Identifier: MIT
/// @file
/// The passive multipole closest to a target, for fixed poles (docs/passivity.md).
///
/// With the poles fixed, G(jω) = Σ_k r_k φ_k(ω) is linear in the residues r (model/residue_basis.hpp),
/// and so is Re G(jω) ≥ 0 at every ω. "The passive model with these poles closest to the target" is then
/// the convex problem
///
///   min_r Σ_i w_i² |t_i − Σ_k r_k φ_k(ω_i)|²   s.t.   Re Σ_k r_k φ_k(ω_j) ≥ δ   for ω_j ∈ Ω,
///
/// solved exactly (numerics/least_squares_inequality.hpp) on a finite constraint set Ω, then certified for
/// every ω ≥ 0 by the Hamiltonian test (model/passivity.hpp). Frequencies where the test still finds
/// Re G < 0 are added to Ω and the problem is solved again (constraint generation, Kelley's cutting
/// planes); since the certified set only grows, this ends in a few rounds. δ > 0 is a margin of 1e-9 of
/// the target's scale that keeps the certificate robust against rounding; where 30 rounds do not close a
/// narrow dip, 1e-6 and then 1e-4 of it are tried (constraints kept).
#pragma once

#include "model/order.hpp"
#include "model/passivity.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen::passivity {

/// What the residues are fitted to: complex values t at angular frequencies ω (rad/s), weights w ≥ 0, and
/// optionally the fit's Gaussian residue prior (docs/passivity.md, "Under the residue prior").
struct ResidueTarget {
  Eigen::ArrayXd omega;
  Eigen::ArrayXcd values;
  Eigen::ArrayXd weights;
  /// σ of the weighted residual per real component; > 0 adds the prior r_k ~ N(0, s_k²) (s_k of
  /// inference/priors.hpp, gaussian_residue_scales, at admittance_scale) as the rows σ r_k / s_k, so the
  /// least squares become the MAP residues under the constraints. 0: unpenalised least squares.
  double noise_sd = 0.0;
  double admittance_scale = 1.0;
};

struct PassiveResidues {
  Eigen::VectorXd theta;               ///< the given poles with the fitted residues
  PassivityResult certificate; ///< the Hamiltonian test of theta (certificate.passive when certified)
  bool certified = false;
  int rounds = 0;                      ///< constraint-generation rounds (1 = the first grid sufficed)
  int constraints = 0;                 ///< size of the final constraint set Ω
  double margin_fraction = 0.0;        ///< δ / max|t| of the certified solution (1e-9 unless it needed more)
  /// The constraint solve failed numerically (a basis too ill-conditioned for it: nearly coincident poles);
  /// theta then holds the residues of the last successful round, or the input's. Not certified.
  bool solve_failed = false;
};

/// The margin δ = fraction · max|t| of the constraints Re G ≥ δ (fraction 1e-9 first, see the file comment).
double constraint_margin(const ResidueTarget& target, double fraction);

/// The first constraint set Ω (rad/s, ascending, distinct): ω = 0, ω = ∞, 31 points across each pair's
/// resonance (model/passivity.hpp, resonance_points) and a log grid of 16 points per decade from 1e-3 × the
/// slowest pole or target frequency to 1e3 × the fastest (Re G of a pole term varies on the scale of its own
/// rate). The certificate adds whatever this misses.
std::vector<double> constraint_grid(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target);

/// The weighted least-squares system of the residues, [w Re Φ; w Im Φ] r ≈ [w Re t; w Im t] (2N rows), plus,
/// when target.noise_sd > 0, the prior's rows diag(σ/s_k) r ≈ 0 (residue_count(order) more rows).
void weighted_system(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target, Eigen::MatrixXd& e,
                     Eigen::VectorXd& f);

/// σ/s_k of the prior's rows for theta's poles (zeros when target.noise_sd = 0), residue_basis order.
Eigen::VectorXd prior_row_weights(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target);

/// Residues of `theta`'s poles (its residues are ignored) closest to `target` subject to passivity.
/// Requires every λ, α > 0. Not certified only if the rounds of every margin are exhausted or the solve fails
/// (solve_failed; reported, never hidden).
PassiveResidues passive_residues(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target);

}  // namespace admitgen::passivity

// SPDX-License-Identifier: MIT
/// @file
/// How well any passive admittance can fit a target: the passive bound (docs/passivity.md, "The passive bound").
///
/// A stable G with a finite G∞ is passive exactly when u(ω) = Re G(jω) ≥ 0 for every ω, and u then fixes G:
/// the imaginary part is its Hilbert transform (causality; for a real response, with e^{+jωt},
///
///   Im G(jω) = (2ω/π) PV ∫₀^∞ u(ω') / (ω'² − ω²) dω'
///
/// (Kramers–Kronig; Bode, *Network Analysis and Feedback Amplifier Design*, 1945, ch. 14). So the passive
/// admittances form a convex cone: every non-negative combination of passive terms is passive. Here the cone is
/// spanned by a dictionary of passive terms, and the best passive fit in it is a non-negative least-squares
/// problem (least_squares_inequality.hpp):
///   - a constant (u = 1);
///   - hats: u piecewise linear in ω, 1 at one node of a log grid of kHatsPerDecade nodes per decade over
///     [ω_min / 10, 10 ω_max], 0 at the two neighbouring nodes; Im G in closed form (below). Any continuous u ≥ 0
///     is approached by its interpolant, which is again ≥ 0;
///   - far terms λ/(λ + jω) and jω/(λ + jω) (u falling or rising about λ), kFarPerDecade per decade of λ over
///     [ω_min / 1000, 1000 ω_max], for what lies beyond the hats.
/// The fit is a passive model with many terms, so its residual is an upper bound on the best passive fit; refining
/// the dictionary lowers it by little (docs/passivity.md gives the figures). A sampled model that fits far better
/// than this bound does so with Re G < 0 somewhere: the data are then not those of a causal passive wall, and no
/// passive filter can follow them.
#pragma once

#include <Eigen/Core>

namespace admitgen::numerics {

struct PassiveBound {
  static constexpr int kHatsPerDecade = 128;
  static constexpr int kFarPerDecade = 16;
  /// √(Σ w_i² |t_i − G(jω_i)|² / Σ w_i² |t_i|²) of the best passive fit over the dictionary.
  double relative_rms_residual = 0.0;
  int terms = 0;       ///< dictionary terms with a non-zero weight in that fit
  int dictionary = 0;  ///< terms offered
  Eigen::ArrayXcd fitted;  ///< the best passive fit at each frequency
};

/// The best passive fit to the complex `values` at angular frequencies `omega` (> 0, rad/s) with weights `weights`
/// over the dictionary above.
PassiveBound passive_bound(const Eigen::ArrayXd& omega, const Eigen::ArrayXcd& values, const Eigen::ArrayXd& weights);

}  // namespace admitgen::numerics

// SPDX-License-Identifier: MIT
/// @file
/// Draws of the residues r from their conditional posterior given the poles: the multivariate Student
/// t of inference/residue_marginal.hpp truncated to the residue box (docs/method.md, "The complete
/// posterior").
#pragma once

#include "core/rng.hpp"
#include "inference/residue_marginal.hpp"

#include <Eigen/Core>

namespace admitgen {

/// How a draw was made.
enum class ResidueDrawMethod {
  rejection,  ///< exact: untruncated t draws until one falls in the box
  gibbs,      ///< rejection failed kRejectionTries times (box mass below ~1 %): Gibbs sweeps
};

/// One draw of the untruncated conditional t: r̂ + √(S_min/W) D L̃⁻ᵀ z (see draw_residues).
Eigen::VectorXd untruncated_residue_draw(const ResidueConditional& c, Rng& rng);

/// Whether r lies in the box [lo, hi].
bool in_residue_box(const Eigen::VectorXd& r, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);

/// Draws r ~ t_ν(r̂, S_min/ν · M⁻¹) restricted to [lo, hi].
///
/// Rejection: r = r̂ + √(S_min/W) D L̃⁻ᵀ z, z ~ N(0, I_p), W ~ χ²_ν (then Cov = M⁻¹ S_min/(ν − 2)),
/// repeated until r is in the box: exact. When `tries` rejections fail, a Gibbs chain of `sweeps`
/// sweeps from r̂ clamped to the box, each coordinate drawn from its exact univariate conditional,
/// r_k | r_−k ~ t_{K−1}(c_k, (S_min + Q_−k)/(M_kk (K − 1))) truncated to [lo_k, hi_k], with
/// c_k = r̂_k − Σ_{j≠k} M_kj (r_j − r̂_j)/M_kk and Q_−k = yᵀMy − M_kk (r_k − c_k)², y = r − r̂
/// (the chain leaves the target invariant; the caller reports how many draws used it).
Eigen::VectorXd draw_residues(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                              Rng& rng, ResidueDrawMethod& method, int tries = 200, int sweeps = 50);

}  // namespace admitgen

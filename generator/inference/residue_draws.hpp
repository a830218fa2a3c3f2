// SPDX-License-Identifier: MIT
/// @file
/// Draws of the residues r from their conditional posterior given the poles: the multivariate Student
/// t of inference/residue_marginal.hpp truncated to the residue box (docs/method.md, "The complete
/// posterior").
#pragma once

#include "core/rng.hpp"
#include "inference/residue_marginal.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen {

/// How a draw was made.
enum class ResidueDrawMethod {
  rejection,  ///< exact: untruncated t draws until one falls in the box
  gibbs,      ///< rejection failed kRejectionTries times (box mass below ~1 %): Gibbs sweeps
};

/// One draw of the untruncated conditional t: r̂ + √(S_min/W) D L̃⁻ᵀ z (see draw_residues).
Eigen::VectorXd untruncated_residue_draw(const ResidueConditional& c, Rng& rng);

/// Unbiased estimates of the box mass P_box of the conditional t by the GHK simulator (Geweke,
/// Hajivassiliou and Keane; Genz 1992, J. Comput. Graph. Stat. 1, 141-149, for the variable ordering):
/// given W ~ χ²_ν the deviation y − ŷ (y = D⁻¹r) is N(0, S_min/W · M̃⁻¹); with the Cholesky factor C of
/// M̃⁻¹ in an ordering of the coordinates by increasing marginal box mass (most constrained first),
/// coordinate i depends on u_0..u_i only, so one replicate is Π_i P(l_i ≤ u_i ≤ h_i) with u_i drawn from
/// N(0, 1) truncated to [l_i, h_i] (exact inversion) before the next factor. Each replicate lies in
/// [0, 1] and has expectation P_box exactly (docs/method.md, "Truncation by the residue box"); unlike the
/// hit rate of untruncated draws its relative variance stays bounded where P_box is tiny. Where r̂ lies
/// outside the box the u_i are drawn around the mode of the truncated normal instead of 0, each factor
/// times its likelihood ratio (docs/method.md, "Tilting the box-mass replicate"): same expectation, lower
/// variance; then a replicate may exceed 1.
class BoxMassSimulator {
 public:
  BoxMassSimulator(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);
  double draw(Rng& rng);  ///< one replicate
  /// ln of the replicate made from given randomness: W (a χ²_ν value, e.g. chi_square_quantile) and p
  /// uniforms in [0, 1), one per coordinate in the simulator's order, each turned into u_i by inversion
  /// (inference/normal_interval.hpp). With `deviation` also the r − r̂ those u_i make: a draw of the
  /// truncated t whose importance weight is the replicate. As a function of (W, uniforms) uniform on
  /// their cube, its integral is P_box exactly (docs/method.md, "Sampling the box mass").
  double log_replicate(double w, const double* uniforms, Eigen::VectorXd* deviation);

 private:
  const ResidueConditional& c_;
  std::vector<Eigen::Index> order_;
  Eigen::MatrixXd chol_;        ///< lower Cholesky factor of M̃⁻¹ in order_
  Eigen::VectorXd a_, b_, u_;   ///< bounds of y − ŷ per coordinate (order_), the drawn normals
  Eigen::VectorXd uniforms_;    ///< draw()'s uniforms
  Eigen::VectorXd tilt_;        ///< v*: the mean shift of the u_i is v*·√(W/S_min) (zero when r̂ is in the box)
};

/// The mean of m ≥ 2 replicates of BoxMassSimulator (an unbiased P̂) and their sample variance.
struct BoxMassEstimate {
  double mean = 0.0;
  double sample_variance = 0.0;
};
BoxMassEstimate estimate_box_mass(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                  long m, Rng& rng);

/// The χ²_ν quantile at u ∈ [0, 1) (Boost.Math's inverse regularised incomplete gamma): W for
/// BoxMassSimulator::log_replicate from a uniform coordinate.
double chi_square_quantile(double nu, double u);

/// Whether r lies in the box [lo, hi].
bool in_residue_box(const Eigen::VectorXd& r, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);

/// The minimiser y* of (y − ŷ)ᵀM̃(y − ŷ) over the box [lo, hi] in Jacobi-scaled coordinates y = D⁻¹r
/// (M̃ = L̃L̃ᵀ, ŷ = D⁻¹r̂; inference/box_least_squares.hpp): the residues of best fit inside the prior box are D y*.
Eigen::VectorXd scaled_box_minimiser(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);

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

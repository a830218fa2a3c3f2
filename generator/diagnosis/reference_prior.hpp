// SPDX-License-Identifier: MIT
/// @file
/// A reference density on one coordinate u ∈ [0, 1] of the prior's unit cube, for sampling a joint
/// candidate of the combined search where earlier runs already know its posterior (docs/method.md,
/// "Reference priors in the combined search"):
///
///   q(u) = ε + (1 − ε) N(u; c, s) / (Φ((1 − c)/s) − Φ(−c/s))   (a normal truncated to [0, 1], plus a
///   uniform share ε that keeps q ≥ ε, so L/q ≤ L/ε wherever the posterior turns out to be).
///
/// The evidence is unchanged: Z = ∫ L(θ(u)) du = ∫ [L(θ(u))/q(u)] q(u) du, so nested sampling of the
/// likelihood L/q over the measure q (the cube mapped through q's inverse CDF) integrates the same Z and
/// its posterior weights are those of L. Only the run's length changes: it compresses from q to the
/// posterior (information KL(post ‖ q)) instead of from the prior.
#pragma once


namespace admitgen::diagnosis {

class ReferenceDensity {
 public:
  /// The uniform density (q = 1).
  ReferenceDensity() = default;
  /// Centre c and width s of the normal, uniform share ε ∈ (0, 1].
  ReferenceDensity(double centre, double width, double uniform_share);

  /// The reference of a coordinate whose posterior has the 95 % interval [u_lo, u_hi] in u (a quantile
  /// of θ maps to u exactly through the prior's CDF): centre and standard deviation from the interval
  /// as for a normal, the width `widening` times that. Uniform when the interval is empty or not finite.
  static ReferenceDensity from_interval(double u_lo, double u_hi, double widening, double uniform_share);

  bool uniform() const { return share_ >= 1.0; }
  /// u = Q⁻¹(v), Q the CDF of q (safeguarded Newton, to about 1e-15 of the cube).
  double inverse_cdf(double v) const;
  /// ln q(u).
  double log_density(double u) const;
  /// Q(u), the CDF of q.
  double cdf(double u) const;

 private:
  double centre_ = 0.5, width_ = 1.0, share_ = 1.0;
  double phi_lo_ = 0.0, mass_ = 1.0;  ///< Φ(−c/s) and Φ((1 − c)/s) − Φ(−c/s)
};

}  // namespace admitgen::diagnosis

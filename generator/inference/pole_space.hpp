// SPDX-License-Identifier: MIT
/// @file
/// The pole coordinates of an order, sampled when the residues are integrated out analytically
/// (docs/method.md, "Sampling the poles only"). ψ = (λ_1, …, λ_Q, α_1, β_1, …, α_S, β_S), Q + 2S
/// numbers; together with the residues r (model/residue_basis.hpp) they make up θ (model/order.hpp).
#pragma once

#include "inference/priors.hpp"
#include "model/order.hpp"

#include <Eigen/Core>

#include <vector>

namespace admitgen {

/// Q + 2S.
int pole_count(const Order& order);

/// Indices into θ of ψ, in the order above.
std::vector<int> pole_indices(const Order& order);

/// θ assembled from poles ψ and residues r.
void assemble_theta(const Order& order, const double* poles, const Eigen::VectorXd& residues, double* theta);

/// ln of the prior volume of the residue box, Σ ln(hi − lo) over r.
double log_residue_box_volume(const Order& order, const PriorRanges& ranges);

/// The residue box as per-residue bounds, in residue_basis order.
void residue_box(const Order& order, const PriorRanges& ranges, Eigen::VectorXd& lo, Eigen::VectorXd& hi);

/// Uniform prior on ψ through the unit cube, with the symmetry fold of PriorTransform restricted to
/// the poles (the marginal likelihood keeps every symmetry of the full one: the residue boxes are
/// the same for every pole of a kind, and the C box is symmetric under reduction).
class PoleTransform {
 public:
  PoleTransform(const Order& order, const PriorRanges& ranges, bool reduce_symmetry);
  void operator()(const double* u, double* poles) const;
  /// Folds u (pole coordinates) to its canonical copy: the full fold applied with every residue
  /// coordinate at u = ½, which the fold's flips (u → 1 − u) leave in place.
  void fold(double* u) const;
  int dim() const { return static_cast<int>(indices_.size()); }

 private:
  PriorTransform full_;  ///< for its fold
  std::vector<int> indices_;
  std::vector<double> lo_, width_;  ///< of each pole coordinate's range
  mutable std::vector<double> u_full_;
};

}  // namespace admitgen

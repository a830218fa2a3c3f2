// SPDX-License-Identifier: MIT
#include "inference/pole_space.hpp"

#include "core/errors.hpp"
#include "model/residue_basis.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen {

int pole_count(const Order& order) { return order.q() + 2 * order.s(); }

std::vector<int> pole_indices(const Order& order) {
  std::vector<int> idx;
  for (int q = 0; q < order.q(); ++q) idx.push_back(Order::lambda(q));
  for (int s = 0; s < order.s(); ++s) {
    idx.push_back(order.alpha(s));
    idx.push_back(order.beta(s));
  }
  return idx;
}

void assemble_theta(const Order& order, const double* poles, const Eigen::VectorXd& residues, double* theta) {
  const auto p = pole_indices(order);
  for (std::size_t k = 0; k < p.size(); ++k) theta[p[k]] = poles[k];
  const auto r = residue_indices(order);
  ADMITGEN_ENSURE(residues.size() == static_cast<Eigen::Index>(r.size()), "{} residues for {}", residues.size(),
                  order.name());
  for (std::size_t k = 0; k < r.size(); ++k) theta[r[k]] = residues[static_cast<Eigen::Index>(k)];
}

void residue_box(const Order& order, const PriorRanges& ranges, Eigen::VectorXd& lo, Eigen::VectorXd& hi) {
  const auto families = order.families();
  const auto idx = residue_indices(order);
  lo.resize(static_cast<Eigen::Index>(idx.size()));
  hi.resize(lo.size());
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const Range& r = ranges.of(families[static_cast<std::size_t>(idx[k])]);
    lo[static_cast<Eigen::Index>(k)] = r.lo;
    hi[static_cast<Eigen::Index>(k)] = r.hi;
  }
}

double log_residue_box_volume(const Order& order, const PriorRanges& ranges) {
  Eigen::VectorXd lo, hi;
  residue_box(order, ranges, lo, hi);
  return (hi - lo).array().log().sum();
}

PoleTransform::PoleTransform(const Order& order, const PriorRanges& ranges, bool reduce_symmetry)
    : full_(order, ranges, reduce_symmetry),
      indices_(pole_indices(order)),
      u_full_(static_cast<std::size_t>(order.dim()), 0.5) {
  const auto families = order.families();
  for (int i : indices_) {
    const Range& r = ranges.of(families[static_cast<std::size_t>(i)]);
    lo_.push_back(r.lo);
    width_.push_back(r.width());
  }
}

void PoleTransform::operator()(const double* u, double* poles) const {
  // PriorTransform's map of each pole coordinate (uniform over its range), without its residues.
  for (std::size_t k = 0; k < indices_.size(); ++k) poles[k] = lo_[k] + width_[k] * u[k];
}

void PoleTransform::fold(double* u) const {
  std::fill(u_full_.begin(), u_full_.end(), 0.5);
  for (std::size_t k = 0; k < indices_.size(); ++k) u_full_[static_cast<std::size_t>(indices_[k])] = u[k];
  full_.fold(u_full_.data());
  for (std::size_t k = 0; k < indices_.size(); ++k) u[k] = u_full_[static_cast<std::size_t>(indices_[k])];
}

}  // namespace admitgen

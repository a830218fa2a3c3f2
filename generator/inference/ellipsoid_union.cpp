// SPDX-License-Identifier: MIT
#include "inference/ellipsoid_union.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen {

EllipsoidUnion::EllipsoidUnion(const Eigen::MatrixXd& u, const LivePointClusters& clusters, double enlarge) {
  const Eigen::Index dim = u.rows();
  ADMITGEN_ENSURE(dim >= 1 && enlarge >= 1.0, "dimension {}, enlargement {}", dim, enlarge);
  const double log_stretch = std::log(enlarge) / static_cast<double>(dim);  // ln f
  for (std::size_t k = 0; k < clusters.axes.size(); ++k) {
    std::vector<Eigen::Index> members;
    for (std::size_t i = 0; i < clusters.label.size(); ++i)
      if (clusters.label[i] == static_cast<int>(k)) members.push_back(static_cast<Eigen::Index>(i));
    if (members.empty()) continue;
    Eigen::VectorXd centre = Eigen::VectorXd::Zero(dim);
    for (Eigen::Index i : members) centre += u.col(i);
    centre /= static_cast<double>(members.size());
    const Eigen::MatrixXd& chol = clusters.axes[k];
    double radius_sq = 0.0;  // s_k², the largest whitened squared distance of a member
    for (Eigen::Index i : members)
      radius_sq = std::max(radius_sq, chol.triangularView<Eigen::Lower>().solve(u.col(i) - centre).squaredNorm());
    const double log_radius = 0.5 * std::log(std::max(radius_sq, 1e-300)) + log_stretch;
    Ellipsoid e{centre, std::exp(log_radius) * chol, 0.0};
    e.log_volume = e.axes.diagonal().array().abs().log().sum();
    ellipsoids_.push_back(std::move(e));
  }
  ADMITGEN_ENSURE(!ellipsoids_.empty(), "no cluster to bound");
  double top = ellipsoids_.front().log_volume;
  for (const Ellipsoid& e : ellipsoids_) top = std::max(top, e.log_volume);
  double sum = 0.0;
  for (const Ellipsoid& e : ellipsoids_) {
    sum += std::exp(e.log_volume - top);
    cumulative_.push_back(sum);
  }
  for (double& c : cumulative_) c /= sum;
  cumulative_.back() = 1.0;
  log_volume_ = top + std::log(sum);
  z_.resize(dim);
}

bool EllipsoidUnion::contains(std::size_t k, const Eigen::VectorXd& x) const {
  const Ellipsoid& e = ellipsoids_[k];
  return e.axes.triangularView<Eigen::Lower>().solve(x - e.centre).squaredNorm() <= 1.0;
}

bool EllipsoidUnion::draw(Rng& rng, Eigen::VectorXd& x, int& cluster) const {
  const double pick = rng.uniform();
  const std::size_t k = static_cast<std::size_t>(
      std::upper_bound(cumulative_.begin(), cumulative_.end() - 1, pick) - cumulative_.begin());
  // Uniform in the unit ball: an isotropic direction times a radius with density ∝ r^{d−1} on [0, 1].
  const Eigen::Index dim = z_.size();
  for (Eigen::Index i = 0; i < dim; ++i) z_[i] = rng.normal();
  const double radius = std::pow(rng.uniform(), 1.0 / static_cast<double>(dim));
  const Ellipsoid& e = ellipsoids_[k];
  x = e.centre + e.axes.triangularView<Eigen::Lower>() * (radius / z_.norm() * z_);
  cluster = static_cast<int>(k);
  if (ellipsoids_.size() == 1) return true;
  int multiplicity = 0;
  for (std::size_t j = 0; j < ellipsoids_.size(); ++j) multiplicity += (j == k || contains(j, x)) ? 1 : 0;
  return multiplicity == 1 || rng.uniform() * multiplicity < 1.0;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "inference/live_point_clusters.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen {
namespace {

Eigen::MatrixXd covariance(const Eigen::MatrixXd& u) {
  const Eigen::VectorXd mean = u.rowwise().mean();
  const Eigen::MatrixXd centred = u.colwise() - mean;
  Eigen::MatrixXd cov = centred * centred.transpose() / static_cast<double>(std::max<Eigen::Index>(u.cols() - 1, 1));
  cov.diagonal().array() += 1e-12 * std::max(cov.diagonal().maxCoeff(), 1e-300);
  return cov;
}

/// ln √det Σ from the Cholesky factor.
double log_volume(const Eigen::MatrixXd& chol) { return chol.diagonal().array().log().sum(); }

Eigen::MatrixXd columns(const Eigen::MatrixXd& u, const std::vector<Eigen::Index>& idx) {
  Eigen::MatrixXd out(u.rows(), static_cast<Eigen::Index>(idx.size()));
  for (std::size_t k = 0; k < idx.size(); ++k) out.col(static_cast<Eigen::Index>(k)) = u.col(idx[k]);
  return out;
}

/// 2-means in whitened coordinates w = L⁻¹(u − mean), seeded by the point farthest from the mean and
/// the point farthest from that one. Returns the member lists of the two halves.
std::pair<std::vector<Eigen::Index>, std::vector<Eigen::Index>> bisect(const Eigen::MatrixXd& u,
                                                                     const Eigen::MatrixXd& chol) {
  const Eigen::VectorXd mean = u.rowwise().mean();
  const Eigen::MatrixXd w = chol.triangularView<Eigen::Lower>().solve(u.colwise() - mean);
  Eigen::Index a = 0, b = 0;
  w.colwise().squaredNorm().maxCoeff(&a);
  (w.colwise() - w.col(a)).colwise().squaredNorm().maxCoeff(&b);
  Eigen::VectorXd ca = w.col(a), cb = w.col(b);
  std::vector<int> side(static_cast<std::size_t>(u.cols()), -1);
  for (int iter = 0; iter < 50; ++iter) {
    bool changed = false;
    Eigen::VectorXd sa = Eigen::VectorXd::Zero(w.rows()), sb = sa;
    int na = 0, nb = 0;
    for (Eigen::Index i = 0; i < w.cols(); ++i) {
      const int s = (w.col(i) - ca).squaredNorm() <= (w.col(i) - cb).squaredNorm() ? 0 : 1;
      changed |= side[static_cast<std::size_t>(i)] != s;
      side[static_cast<std::size_t>(i)] = s;
      (s == 0 ? sa : sb) += w.col(i);
      ++(s == 0 ? na : nb);
    }
    if (!changed || na == 0 || nb == 0) break;
    ca = sa / na;
    cb = sb / nb;
  }
  std::pair<std::vector<Eigen::Index>, std::vector<Eigen::Index>> halves;
  for (Eigen::Index i = 0; i < u.cols(); ++i) (side[static_cast<std::size_t>(i)] == 0 ? halves.first : halves.second).push_back(i);
  return halves;
}

}  // namespace

Eigen::MatrixXd covariance_axes(const Eigen::MatrixXd& u) {
  const Eigen::MatrixXd cov = covariance(u);
  Eigen::LLT<Eigen::MatrixXd> llt(cov);
  if (llt.info() == Eigen::Success) return llt.matrixL();
  Eigen::MatrixXd diag = Eigen::MatrixXd::Zero(cov.rows(), cov.cols());
  diag.diagonal() = cov.diagonal().cwiseSqrt();
  return diag;
}

LivePointClusters cluster_live_points(const Eigen::MatrixXd& u, int min_size, int max_clusters) {
  struct Node {
    std::vector<Eigen::Index> members;
    Eigen::MatrixXd axes;
    bool final = false;
  };
  std::vector<Eigen::Index> all(static_cast<std::size_t>(u.cols()));
  for (Eigen::Index i = 0; i < u.cols(); ++i) all[static_cast<std::size_t>(i)] = i;
  std::vector<Node> nodes{{all, covariance_axes(u), false}};
  for (bool progress = true; progress && static_cast<int>(nodes.size()) < max_clusters;) {
    progress = false;
    for (std::size_t k = 0; k < nodes.size() && static_cast<int>(nodes.size()) < max_clusters; ++k) {
      if (nodes[k].final) continue;
      const Eigen::MatrixXd pts = columns(u, nodes[k].members);
      auto [first, second] = bisect(pts, nodes[k].axes);
      bool split = static_cast<int>(first.size()) >= min_size && static_cast<int>(second.size()) >= min_size;
      Eigen::MatrixXd axes_a, axes_b;
      if (split) {
        axes_a = covariance_axes(columns(pts, first));
        axes_b = covariance_axes(columns(pts, second));
        const double la = log_volume(axes_a), lb = log_volume(axes_b), lp = log_volume(nodes[k].axes);
        const double l_sum = std::max(la, lb) + std::log1p(std::exp(-std::abs(la - lb)));
        split = l_sum < lp + std::log(0.5);
      }
      if (!split) {
        nodes[k].final = true;
        continue;
      }
      for (auto& i : first) i = nodes[k].members[static_cast<std::size_t>(i)];
      for (auto& i : second) i = nodes[k].members[static_cast<std::size_t>(i)];
      nodes[k] = Node{std::move(first), std::move(axes_a), false};
      nodes.push_back(Node{std::move(second), std::move(axes_b), false});
      progress = true;
    }
  }
  LivePointClusters out;
  out.label.assign(static_cast<std::size_t>(u.cols()), 0);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    for (Eigen::Index i : nodes[k].members) out.label[static_cast<std::size_t>(i)] = static_cast<int>(k);
    out.axes.push_back(std::move(nodes[k].axes));
  }
  return out;
}

}  // namespace admitgen

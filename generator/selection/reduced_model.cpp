// SPDX-License-Identifier: MIT
#include "selection/reduced_model.hpp"

#include "core/errors.hpp"
#include "inference/box_least_squares.hpp"
#include "inference/pole_space.hpp"
#include "inference/residue_evidence.hpp"

#include <bitset>
#include <cmath>
#include <limits>
#include <vector>

namespace admitgen {

namespace {

/// Every subset of {0, …, n − 1} with k members, as bit masks (n ≤ Order::kMaxPoles).
std::vector<unsigned> subsets(int n, int k) {
  std::vector<unsigned> out;
  for (unsigned mask = 0; mask < (1u << n); ++mask)
    if (static_cast<int>(std::bitset<32>(mask).count()) == k) out.push_back(mask);
  return out;
}

}  // namespace

double reduced_log_likelihood(const Measurement& data, const Order& small, const Order& big, const double* theta_big,
                              const PriorRanges& priors, DataCount count) {
  ADMITGEN_ENSURE(small.q() <= big.q() && small.s() <= big.s(), "{} is not contained in {}",
                  small.name(), big.name());
  const ResidueEvidence evidence(data, small, count, 1.0);
  const Likelihood likelihood(data, small, count);
  const bool boxed = priors.residues == ResiduePrior::uniform;
  Eigen::VectorXd lo, hi;
  residue_box(small, priors, lo, hi);
  std::vector<double> poles(static_cast<std::size_t>(pole_count(small)));
  std::vector<double> theta(static_cast<std::size_t>(small.dim()));
  double best = -std::numeric_limits<double>::infinity();
  for (unsigned real : subsets(big.q(), small.q()))
    for (unsigned pairs : subsets(big.s(), small.s())) {
      // ψ of the smaller order (inference/pole_space.hpp packing): the kept λ, then the kept (α, β).
      std::size_t k = 0;
      for (int q = 0; q < big.q(); ++q)
        if (real & (1u << q)) poles[k++] = theta_big[Order::lambda(q)];
      for (int s = 0; s < big.s(); ++s)
        if (pairs & (1u << s)) {
          poles[k++] = theta_big[big.alpha(s)];
          poles[k++] = theta_big[big.beta(s)];
        }
      const ResiduePosterior& c = evidence.posterior(poles.data());
      if (!c.valid) continue;
      // The least-squares residues; under the uniform prior, min over its box of (r − r̂)ᵀM(r − r̂), solved in
      // the coordinates of the Gaussian prior's scales, where M̃ = V diag(μ) Vᵀ is well scaled (the residues of the
      // columns differ by orders of magnitude; docs/method.md, "Residues given the poles").
      Eigen::VectorXd r = least_squares_residues(c);
      if (boxed) {
        const Eigen::VectorXd inv = c.sd.cwiseInverse();
        const Eigen::MatrixXd m_scaled = c.v * c.mu.asDiagonal() * c.v.transpose();
        r = box_least_squares(m_scaled, r.cwiseProduct(inv), lo.cwiseProduct(inv), hi.cwiseProduct(inv)).cwiseProduct(c.sd);
        r = r.cwiseMax(lo).cwiseMin(hi);
      }
      assemble_theta(small, poles.data(), r, theta.data());
      const double log_l = likelihood(theta.data());
      if (std::isfinite(log_l) && log_l > best) best = log_l;
    }
  return best;
}

}  // namespace admitgen

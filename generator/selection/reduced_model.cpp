// SPDX-License-Identifier: MIT
#include "selection/reduced_model.hpp"

#include "core/errors.hpp"
#include "inference/box_least_squares.hpp"
#include "inference/pole_space.hpp"
#include "inference/residue_evidence.hpp"

#include <algorithm>
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

/// Appends to `poles` the real poles, then the pairs, of θ (order `from`) selected by the bit masks.
void gather_poles(const Order& from, const double* theta, unsigned real, unsigned pairs, std::vector<double>& poles) {
  for (int q = 0; q < from.q(); ++q)
    if (real & (1u << q)) poles.push_back(theta[Order::lambda(q)]);
  for (int s = 0; s < from.s(); ++s)
    if (pairs & (1u << s)) {
      poles.push_back(theta[from.alpha(s)]);
      poles.push_back(theta[from.beta(s)]);
    }
}

/// ψ packed as inference/pole_space.hpp (every λ, then every (α, β)) from two gather_poles results, `first`
/// with q_first real poles and `second` with q_second.
std::vector<double> packed(const std::vector<double>& first, int q_first, const std::vector<double>& second,
                           int q_second) {
  std::vector<double> psi(first.begin(), first.begin() + q_first);
  psi.insert(psi.end(), second.begin(), second.begin() + q_second);
  psi.insert(psi.end(), first.begin() + q_first, first.end());
  psi.insert(psi.end(), second.begin() + q_second, second.end());
  return psi;
}

unsigned all_of(int n) { return n == 0 ? 0u : (1u << n) - 1u; }

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
  std::vector<double> poles;
  std::vector<double> theta(static_cast<std::size_t>(small.dim()));
  double best = -std::numeric_limits<double>::infinity();
  for (unsigned real : subsets(big.q(), small.q()))
    for (unsigned pairs : subsets(big.s(), small.s())) {
      // ψ of the smaller order (inference/pole_space.hpp packing): the kept λ, then the kept (α, β).
      poles.clear();
      gather_poles(big, theta_big, real, pairs, poles);
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

MarginalPeak marginal_peak(const ResidueEvidence& evidence, const Order& order, const NestedRun& run, int live) {
  MarginalPeak peak;
  if (run.size() == 0) return peak;
  if (!run.sampled_log_likelihood.empty()) {  // the pole sampler's own values: no evaluation needed
    for (std::size_t i = 0; i < run.size(); ++i)
      if (run.sampled_log_likelihood[i] > peak.log_l) peak = {i, run.sampled_log_likelihood[i]};
    return peak;
  }
  const std::size_t first = run.size() > static_cast<std::size_t>(live) + 1 ? run.size() - static_cast<std::size_t>(live) - 1 : 0;
  std::vector<double> psi;
  for (std::size_t i = first; i < run.size(); ++i) {
    psi.clear();
    gather_poles(order, run.point(i), all_of(order.q()), all_of(order.s()), psi);
    const double log_l = evidence(psi.data());
    if (log_l > peak.log_l) peak = {i, log_l};
  }
  return peak;
}

double reduced_log_marginal(const ResidueEvidence& evidence, const Order& small, const Order& big,
                            const double* theta_big) {
  ADMITGEN_ENSURE(small.q() <= big.q() && small.s() <= big.s(), "{} is not contained in {}", small.name(), big.name());
  double best = -std::numeric_limits<double>::infinity();
  std::vector<double> psi;
  for (unsigned real : subsets(big.q(), small.q()))
    for (unsigned pairs : subsets(big.s(), small.s())) {
      psi.clear();
      gather_poles(big, theta_big, real, pairs, psi);
      best = std::max(best, evidence(psi.data()));
    }
  return best;
}

double completed_log_marginal(const ResidueEvidence& evidence, const Order& small, const double* theta_small,
                              const Order& big, const double* theta_big) {
  ADMITGEN_ENSURE(small.q() <= big.q() && small.s() <= big.s(), "{} is not contained in {}", small.name(), big.name());
  std::vector<double> kept;
  gather_poles(small, theta_small, all_of(small.q()), all_of(small.s()), kept);
  double best = -std::numeric_limits<double>::infinity();
  std::vector<double> added;
  for (unsigned real : subsets(big.q(), big.q() - small.q()))
    for (unsigned pairs : subsets(big.s(), big.s() - small.s())) {
      added.clear();
      gather_poles(big, theta_big, real, pairs, added);
      const std::vector<double> psi = packed(kept, small.q(), added, big.q() - small.q());
      best = std::max(best, evidence(psi.data()));
    }
  return best;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "passivity/passive_estimate.hpp"

#include "core/errors.hpp"
#include "model/passivity.hpp"
#include "passivity/passive_residues.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen::passivity {

PassiveEstimate passive_estimate(const Measurement& data, const Order& order,
                                 const std::vector<Eigen::VectorXd>& candidates, DataCount count) {
  ADMITGEN_ENSURE(!candidates.empty(), "passive estimate of {}: no samples", order.name());
  const Likelihood likelihood(data, order, count);
  const double data_norm2 = data.y.abs2().sum();
  const auto rel_rms = [&](const Eigen::VectorXd& th) {
    return std::sqrt(likelihood.sum_squared_residual(th.data()) / data_norm2);
  };
  // The likelihood weighs every point's complex residual equally: unit weights.
  const ResidueTarget target{data.omega(), data.y, Eigen::ArrayXd::Ones(data.size())};
  PassiveEstimate best;
  bool have = false;
  const int n = std::min<int>(PassiveEstimate::kCandidates, static_cast<int>(candidates.size()));
  for (int k = 0; k < n; ++k) {
    const Eigen::VectorXd& sample = candidates[static_cast<std::size_t>(k)];
    PassiveEstimate e;
    e.candidate_rank = k;
    const PassivityResult as_is = continuous_passivity(order, sample.data());
    if (as_is.passive) {
      e.theta = sample;
      e.certified = true;
      e.min_re = as_is.min_re;
    } else {
      const PassiveResidues p = passive_residues(order, sample, target);
      e.theta = p.theta;
      e.certified = p.certified;
      e.min_re = p.certificate.min_re;
      e.rounds = p.rounds;
      e.changed = true;
    }
    e.log_likelihood = likelihood(e.theta.data());
    // A certified candidate beats an uncertified one; then the higher likelihood wins.
    if (!have || (e.certified && !best.certified) ||
        (e.certified == best.certified && e.log_likelihood > best.log_likelihood))
      best = e, have = true;
    if (k == 0 && as_is.passive) break;  // the best sample itself is passive: nothing can beat it
  }
  best.best_sample_log_likelihood = likelihood(candidates.front().data());
  best.best_sample_relative_rms_residual = rel_rms(candidates.front());
  best.relative_rms_residual = rel_rms(best.theta);
  return best;
}

DataPassivity data_passivity(const Measurement& data) {
  DataPassivity d;
  d.min_re = data.y.real().minCoeff();
  d.negative_points = static_cast<int>((data.y.real() < 0.0).count());
  return d;
}

}  // namespace admitgen::passivity

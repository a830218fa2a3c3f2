#include "passivity/passive_estimate.hpp"

#include "checks/passivity.hpp"
#include "passivity/passive_residues.hpp"

#include <cmath>

namespace admitgen::passivity {

PassiveEstimate passive_estimate(const Measurement& data, const Order& order, const Eigen::VectorXd& best,
                                 DataCount count) {
  const Likelihood likelihood(data, order, count);
  const double data_norm2 = data.y.abs2().sum();
  const auto rel_rms = [&](const Eigen::VectorXd& th) {
    return std::sqrt(likelihood.sum_squared_residual(th.data()) / data_norm2);
  };
  PassiveEstimate e;
  e.best_sample_log_likelihood = likelihood(best.data());
  e.best_sample_relative_rms_residual = rel_rms(best);
  const checks::PassivityResult as_is = checks::continuous_passivity(order, best.data());
  if (as_is.passive) {
    e.theta = best;
    e.certified = true;
    e.min_re = as_is.min_re;
  } else {
    // The likelihood weighs every point's complex residual equally: unit weights.
    const ResidueTarget target{data.omega(), data.y, Eigen::ArrayXd::Ones(data.size())};
    const PassiveResidues p = passive_residues(order, best, target);
    e.theta = p.theta;
    e.certified = p.certified;
    e.min_re = p.certificate.min_re;
    e.rounds = p.rounds;
    e.changed = true;
  }
  e.log_likelihood = likelihood(e.theta.data());
  e.relative_rms_residual = rel_rms(e.theta);
  return e;
}

DataPassivity data_passivity(const Measurement& data) {
  DataPassivity d;
  d.min_re = data.y.real().minCoeff();
  d.negative_points = static_cast<int>((data.y.real() < 0.0).count());
  return d;
}

}  // namespace admitgen::passivity

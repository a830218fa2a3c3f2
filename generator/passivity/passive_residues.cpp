// SPDX-License-Identifier: MIT
#include "passivity/passive_residues.hpp"

#include "core/errors.hpp"
#include "core/log_grid.hpp"
#include "inference/pole_space.hpp"
#include "inference/priors.hpp"
#include "model/passivity.hpp"
#include "model/residue_basis.hpp"
#include "numerics/least_squares_inequality.hpp"


#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace admitgen::passivity {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Margins δ of the constraints, relative to the target's largest |t|, tried in turn: 1e-9 is far above the
/// ~1e-15 rounding of Re G and far below any measurable change of the model; where the rounds cannot close a
/// dip at that margin (a pair a few s⁻¹ wide whose Re G curves faster than the points added can follow),
/// a larger margin lifts Re G across the dip (1e-4 of max|t| is still far below the data's noise).
constexpr double kMarginFractions[] = {1e-9, 1e-6, 1e-4};
/// Initial constraint grid: log-spaced points per decade from 1e-3 × the slowest pole to 1e3 × the
/// fastest (Re G of a pole term varies on the scale of its own rate; 16 per decade resolves it).
constexpr int kPointsPerDecade = 16;
constexpr int kMaxRounds = 30;

/// Violations to add: each negative band's minimum and 9 points spanning it (geometric when it starts
/// above 0 Hz), so one round covers the whole band (rad/s).
void add_violations(const PassivityResult& r, std::vector<double>& omega) {
  const auto rad = [](double hz) { return 2.0 * kPi * hz; };
  for (const auto& b : r.bands) {
    if (std::isfinite(b.at)) omega.push_back(rad(b.at));
    const double hi = std::isfinite(b.hi) ? b.hi : 2.0 * std::max(b.lo, b.at);
    for (int i = 0; i <= 8; ++i)
      omega.push_back(rad(b.lo > 0.0 ? b.lo * std::pow(hi / b.lo, i / 8.0) : hi * i / 8.0));
  }
}

}  // namespace

Eigen::VectorXd prior_row_weights(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& t) {
  Eigen::VectorXd sd(residue_count(order));
  if (t.noise_sd <= 0.0) return Eigen::VectorXd::Zero(sd.size());
  std::vector<double> poles;
  for (const int i : pole_indices(order)) poles.push_back(theta[i]);
  gaussian_residue_scales(order, poles.data(), t.admittance_scale, sd.data());
  return t.noise_sd * sd.cwiseInverse();
}

void weighted_system(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& t, Eigen::MatrixXd& e,
                     Eigen::VectorXd& f) {
  const ResidueBasis b = residue_basis(order, theta, t.omega);
  const Eigen::Index n = t.omega.size(), p = b.re.cols(), extra = t.noise_sd > 0.0 ? p : 0;
  e.resize(2 * n + extra, p);
  f.resize(2 * n + extra);
  e.topRows(n) = t.weights.matrix().asDiagonal() * b.re;
  e.middleRows(n, n) = t.weights.matrix().asDiagonal() * b.im;
  f.head(n) = (t.weights * t.values.real()).matrix();
  f.segment(n, n) = (t.weights * t.values.imag()).matrix();
  if (extra > 0) {
    e.bottomRows(extra) = prior_row_weights(order, theta, t).asDiagonal();
    f.tail(extra).setZero();
  }
}

std::vector<double> constraint_grid(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& t) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  std::vector<double> w{0.0, std::numeric_limits<double>::infinity()};
  for (int q = 0; q < order.q(); ++q) lo = std::min(lo, theta[Order::lambda(q)]), hi = std::max(hi, theta[Order::lambda(q)]);
  for (int s = 0; s < order.s(); ++s) {
    const double m = std::hypot(theta[order.alpha(s)], theta[order.beta(s)]);
    lo = std::min(lo, std::min(m, theta[order.alpha(s)])), hi = std::max(hi, m);
    // The pair's resonance on its own scale (model/passivity.hpp, resonance_points).
    for (const double x : resonance_points(std::abs(theta[order.beta(s)]), theta[order.alpha(s)]))
      if (x > 0.0) w.push_back(x);
  }
  if (t.omega.size() > 0) lo = std::min(lo, t.omega.minCoeff()), hi = std::max(hi, t.omega.maxCoeff());
  if (hi > 0.0) {
    lo = std::max(lo * 1e-3, 1e-300), hi *= 1e3;
    const std::vector<double> grid = log_grid(lo, hi, kPointsPerDecade);
    w.insert(w.end(), grid.begin(), grid.end());
  }
  std::sort(w.begin(), w.end());
  w.erase(std::unique(w.begin(), w.end()), w.end());
  return w;
}

double constraint_margin(const ResidueTarget& target, double fraction) {
  return fraction * std::max(target.values.abs().maxCoeff(), 1e-300);
}

PassiveResidues passive_residues(const Order& order, const Eigen::VectorXd& theta, const ResidueTarget& target) {
  ADMITGEN_ENSURE(target.omega.size() == target.values.size() && target.omega.size() == target.weights.size(),
                  "passive residues: target sizes differ");
  Eigen::MatrixXd e;
  Eigen::VectorXd f;
  weighted_system(order, theta, target, e, f);
  std::vector<double> omega = constraint_grid(order, theta, target);
  PassiveResidues out;
  out.theta = theta;
  for (const double fraction : kMarginFractions) {
    const double margin = constraint_margin(target, fraction);
    for (out.rounds = 1; out.rounds <= kMaxRounds; ++out.rounds) {
      std::sort(omega.begin(), omega.end());
      omega.erase(std::unique(omega.begin(), omega.end()), omega.end());
      const Eigen::ArrayXd w = Eigen::Map<const Eigen::ArrayXd>(omega.data(), Eigen::Index(omega.size()));
      const Eigen::MatrixXd g = residue_basis(order, theta, w).re;  // Re G(jω_j) = g_j · r
      // Solved with 2δ: the slack absorbs the dips of Re G between constraint points (each would cost a round).
      const auto sol = numerics::least_squares_inequality(e, f, g, Eigen::VectorXd::Constant(g.rows(), 2.0 * margin));
      // r = (2δ, 0, …) is feasible in exact arithmetic; a solve that says otherwise (or overflows) met a basis
      // too ill-conditioned for it (nearly coincident poles): reported as not certified, never hidden.
      if (!sol.feasible || !sol.x.allFinite()) {
        out.solve_failed = true;
        return out;
      }
      set_residues(order, sol.x, out.theta);
      out.constraints = static_cast<int>(omega.size());
      out.certificate = continuous_passivity(order, out.theta.data());
      if (out.certificate.passive) {
        out.certified = true;
        out.margin_fraction = fraction;
        return out;
      }
      add_violations(out.certificate, omega);
    }
  }
  out.rounds = kMaxRounds;
  return out;
}

}  // namespace admitgen::passivity

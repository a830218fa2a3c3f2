// SPDX-License-Identifier: MIT
#include "inference/residue_draws.hpp"

#include "inference/student_t.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen {
namespace {

Eigen::VectorXd gibbs(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Rng& rng,
                      int sweeps) {
  const Eigen::Index p = c.mean.size();
  Eigen::VectorXd r = c.mean.cwiseMax(lo).cwiseMin(hi);
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (Eigen::Index k = 0; k < p; ++k) {
      const Eigen::VectorXd y = r - c.mean;
      const double mkk = c.m(k, k);
      const double shift = (c.m.row(k).dot(y) - mkk * y[k]) / mkk;  // Σ_{j≠k} M_kj y_j / M_kk
      const double centre = c.mean[k] - shift;
      const double q_rest = std::max(y.dot(c.m * y) - mkk * (r[k] - centre) * (r[k] - centre), 0.0);
      const double tau = std::sqrt((c.s_min + q_rest) / (mkk * (c.k - 1.0)));
      r[k] = centre + tau * truncated_student_t_draw(c.k - 1.0, (lo[k] - centre) / tau, (hi[k] - centre) / tau, rng);
      r[k] = std::clamp(r[k], lo[k], hi[k]);
    }
  return r;
}

}  // namespace

bool in_residue_box(const Eigen::VectorXd& r, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  return (r.array() >= lo.array()).all() && (r.array() <= hi.array()).all();
}

Eigen::VectorXd untruncated_residue_draw(const ResidueConditional& c, Rng& rng) {
  Eigen::VectorXd z(c.mean.size());
  for (Eigen::Index k = 0; k < z.size(); ++k) z[k] = rng.normal();
  const double w = chi_square_draw(c.nu, rng);
  z = c.chol.transpose().triangularView<Eigen::Upper>().solve(z);  // L̃⁻ᵀ z
  return c.mean + std::sqrt(c.s_min / w) * c.scale.cwiseProduct(z);
}

Eigen::VectorXd draw_residues(const ResidueConditional& c, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                              Rng& rng, ResidueDrawMethod& method, int tries, int sweeps) {
  for (int t = 0; t < tries; ++t) {
    Eigen::VectorXd r = untruncated_residue_draw(c, rng);
    if (in_residue_box(r, lo, hi)) {
      method = ResidueDrawMethod::rejection;
      return r;
    }
  }
  method = ResidueDrawMethod::gibbs;
  return gibbs(c, lo, hi, rng, sweeps);
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "codegen/band_absorption.hpp"

#include "core/errors.hpp"
#include "model/multipole.hpp"

#include <cmath>

namespace admitgen::codegen {

double alpha_normal(std::complex<double> g) {
  const std::complex<double> r = (1.0 - g) / (1.0 + g);
  return 1.0 - std::norm(r);
}

double alpha_random(std::complex<double> g) {
  const std::complex<double> zeta = 1.0 / g;
  const double xi = zeta.real(), eta = zeta.imag(), m2 = std::norm(zeta);
  const double last = std::abs(eta) < 1e-9 * (1.0 + xi) ? xi * xi / (m2 * (1.0 + xi))
                                                          : (xi * xi - eta * eta) / (eta * m2) * std::atan(eta / (1.0 + xi));
  return 8.0 * xi / m2 * (1.0 - xi / m2 * std::log(1.0 + 2.0 * xi + m2) + last);
}

std::vector<BandAbsorption> band_absorption(const Order& order, const Eigen::VectorXd& theta, int fraction,
                                            double data_f_min, double data_f_max) {
  ADMITGEN_ENSURE(fraction == 1 || fraction == 3, "band fraction {}", fraction);
  const double ratio = std::pow(10.0, 0.3 / fraction);  // base-10 band ratio G^{1/b}
  const int k_lo = fraction == 1 ? -5 : -16, k_hi = fraction == 1 ? 4 : 13;
  std::vector<BandEdges> edges;
  for (int k = k_lo; k <= k_hi; ++k) {
    const double center = 1000.0 * std::pow(ratio, k);
    edges.push_back({center, center / std::sqrt(ratio), center * std::sqrt(ratio)});
  }
  return band_absorption(order, theta, edges, data_f_min, data_f_max);
}

std::vector<BandAbsorption> band_absorption(const Order& order, const Eigen::VectorXd& theta,
                                            const std::vector<BandEdges>& edges, double data_f_min, double data_f_max) {
  constexpr int kPoints = 32;
  std::vector<BandAbsorption> bands;
  for (const BandEdges& e : edges) {
    ADMITGEN_ENSURE(0.0 < e.lo_hz && e.lo_hz < e.hi_hz, "band edges {} {}", e.lo_hz, e.hi_hz);
    BandAbsorption b;
    b.center_hz = e.center_hz;
    b.lo_hz = e.lo_hz;
    b.hi_hz = e.hi_hz;
    b.in_data = b.lo_hz >= data_f_min && b.hi_hz <= data_f_max;
    Eigen::ArrayXd omega(kPoints);
    for (int i = 0; i < kPoints; ++i)
      omega[i] = 2.0 * EIGEN_PI * b.lo_hz * std::pow(b.hi_hz / b.lo_hz, (i + 0.5) / kPoints);
    const Eigen::ArrayXcd g = evaluate_multipole(order, theta, omega);
    for (int i = 0; i < kPoints; ++i) {
      b.alpha_normal += alpha_normal(g[i]) / kPoints;
      b.alpha_random += alpha_random(g[i]) / kPoints;
    }
    bands.push_back(b);
  }
  return bands;
}

}  // namespace admitgen::codegen

// SPDX-License-Identifier: MIT
#include "physics/micro_perforated.hpp"

#include <cmath>

namespace admitgen {

Eigen::ArrayXcd panel_impedance(const MicroPerforatedPanel& panel, const Air& air, const Eigen::ArrayXd& f_hz) {
  const double d = panel.hole_diameter, t = panel.thickness, p = panel.perforation;
  const Eigen::ArrayXd omega = 2.0 * EIGEN_PI * f_hz;
  const Eigen::ArrayXd k = d * (omega * air.rho0 / (4.0 * air.eta)).sqrt();
  Eigen::ArrayXcd z(f_hz.size());
  z.real() = (32.0 * air.eta * t / (p * air.rho_c() * d * d)) *
             ((1.0 + k.square() / 32.0).sqrt() + (std::sqrt(2.0) / 32.0) * k * d / t);
  z.imag() = (omega * t / (p * air.c0)) * (1.0 + (9.0 + k.square() / 2.0).rsqrt() + 0.85 * d / t);
  return z;
}

}  // namespace admitgen

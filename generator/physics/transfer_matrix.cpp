// SPDX-License-Identifier: MIT
#include "physics/transfer_matrix.hpp"

#include "core/errors.hpp"
#include "physics/overloaded.hpp"

#include <Eigen/Dense>

#include <complex>

namespace admitgen {
namespace {

using cd = std::complex<double>;
using Matrix2cd = Eigen::Matrix2cd;
constexpr cd kJ{0.0, 1.0};

/// Transfer matrices of one layer at every frequency.
std::vector<Matrix2cd> fluid_matrices(const Propagation& p, double h) {
  std::vector<Matrix2cd> out(static_cast<std::size_t>(p.zc.size()));
  for (Eigen::Index i = 0; i < p.zc.size(); ++i) {
    const cd kh = p.kc[i] * h, zc = p.zc[i];
    const cd c = std::cos(kh), s = std::sin(kh);
    out[static_cast<std::size_t>(i)] << c, kJ * zc * s, kJ * s / zc, c;
  }
  return out;
}

std::vector<Matrix2cd> layer_matrices(const Layer& layer, const Air& air, const Eigen::ArrayXd& f) {
  return std::visit(
      Overloaded{[&](const PorousLayer& l) { return fluid_matrices(propagation(l.model, air, f), l.thickness); },
                 [&](const AirLayer& l) { return fluid_matrices(air_propagation(air, f), l.thickness); },
                 [&](const MicroPerforatedPanel& panel) {
                   const Eigen::ArrayXcd zp = air.rho_c() * panel_impedance(panel, air, f);
                   std::vector<Matrix2cd> out(static_cast<std::size_t>(f.size()));
                   for (Eigen::Index i = 0; i < f.size(); ++i) out[static_cast<std::size_t>(i)] << 1.0, zp[i], 0.0, 1.0;
                   return out;
                 }},
      layer);
}

}  // namespace

double LayeredAbsorber::depth() const {
  double total = 0.0;
  for (const auto& layer : layers)
    total += std::visit(Overloaded{[](const PorousLayer& l) { return l.thickness; },
                                   [](const AirLayer& l) { return l.thickness; },
                                   [](const MicroPerforatedPanel&) { return 0.0; }},
                        layer);
  return total;
}

Eigen::ArrayXcd surface_admittance(const LayeredAbsorber& absorber, const Air& air, const Eigen::ArrayXd& f_hz) {
  ADMITGEN_ENSURE(!absorber.layers.empty(), "a layered absorber needs at least one layer");
  std::vector<Matrix2cd> total(static_cast<std::size_t>(f_hz.size()), Matrix2cd::Identity());
  for (const auto& layer : absorber.layers) {
    const auto t = layer_matrices(layer, air, f_hz);
    for (std::size_t i = 0; i < total.size(); ++i) total[i] = total[i] * t[i];
  }
  Eigen::ArrayXcd y(f_hz.size());
  for (Eigen::Index i = 0; i < f_hz.size(); ++i) {
    const auto& t = total[static_cast<std::size_t>(i)];
    y[i] = air.rho_c() * t(1, 0) / t(0, 0);
  }
  return y;
}

}  // namespace admitgen

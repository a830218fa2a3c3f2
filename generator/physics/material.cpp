// SPDX-License-Identifier: MIT
#include "physics/material.hpp"

#include "physics/overloaded.hpp"

namespace admitgen {

Eigen::ArrayXcd surface_admittance(const Material& material, const Air& air, const Eigen::ArrayXd& f_hz) {
  return std::visit(
      Overloaded{[&](const LayeredAbsorber& m) { return surface_admittance(m, air, f_hz); },
                 [&](const MultipoleSurface& m) { return surface_admittance(m, f_hz); }},
      material);
}

}  // namespace admitgen

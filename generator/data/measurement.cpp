// SPDX-License-Identifier: MIT
#include "data/measurement.hpp"

namespace admitgen {

Eigen::ArrayXd absorption(const Eigen::ArrayXcd& y) {
  const Eigen::ArrayXcd r = (1.0 - y) / (1.0 + y);
  return 1.0 - r.abs2();
}

}  // namespace admitgen

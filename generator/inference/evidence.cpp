// SPDX-License-Identifier: MIT
#include "inference/evidence.hpp"

#include <cmath>

namespace admitgen {

double deciban(double log_z_i, double log_z_j) { return 10.0 * (log_z_i - log_z_j) / std::log(10.0); }

}  // namespace admitgen

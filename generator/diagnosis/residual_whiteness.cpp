// SPDX-License-Identifier: MIT
#include "diagnosis/residual_whiteness.hpp"

#include "core/errors.hpp"

#include <cmath>

namespace admitgen::diagnosis {

Whiteness residual_whiteness(const Eigen::ArrayXcd& r) {
  ADMITGEN_ENSURE(r.size() >= 2, "whiteness needs at least two points, got {}", r.size());
  const Eigen::Index n = r.size();
  const double energy = r.abs2().sum();
  Whiteness w;
  if (!(energy > 0.0)) return w;
  double lagged = 0.0;
  for (Eigen::Index i = 0; i + 1 < n; ++i) lagged += (r[i] * std::conj(r[i + 1])).real();
  w.lag1 = lagged / energy;
  w.z = w.lag1 * std::sqrt(2.0 * static_cast<double>(n - 1));
  w.white = std::abs(w.z) < Whiteness::kWhitenessZ;
  return w;
}

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
#include "diagnosis/third_octave_bands.hpp"

#include "core/errors.hpp"

#include <cmath>

namespace admitgen::diagnosis {

ThirdOctaveBand third_octave_band(int x) {
  ThirdOctaveBand b;
  b.index = x;
  b.f_center = 1000.0 * std::pow(10.0, x / 10.0);
  b.f_lo = b.f_center * std::pow(10.0, -1.0 / 20.0);
  b.f_hi = b.f_center * std::pow(10.0, 1.0 / 20.0);
  return b;
}

std::vector<ThirdOctaveBand> covered_bands(const Eigen::ArrayXd& f_hz) {
  ADMITGEN_ENSURE(f_hz.size() > 0 && f_hz[0] > 0.0, "bands need positive frequencies");
  const double f_min = f_hz[0];
  const double f_max = f_hz[f_hz.size() - 1];
  std::vector<ThirdOctaveBand> bands;
  // x such that f_m ≥ f_min: x ≥ 10 log10(f_min/1000); a small tolerance admits a centre equal to f_min.
  const int x_first = static_cast<int>(std::ceil(10.0 * std::log10(f_min / 1000.0) - 1e-9));
  for (int x = x_first;; ++x) {
    ThirdOctaveBand b = third_octave_band(x);
    if (b.f_center > f_max * (1.0 + 1e-12)) break;
    Eigen::Index i = 0;
    while (i < f_hz.size() && f_hz[i] < b.f_lo) ++i;
    b.first = i;
    while (i < f_hz.size() && b.contains(f_hz[i])) ++i;
    b.count = i - b.first;
    if (b.count > 0) bands.push_back(b);
  }
  return bands;
}

}  // namespace admitgen::diagnosis

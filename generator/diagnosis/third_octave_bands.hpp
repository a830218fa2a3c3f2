// SPDX-License-Identifier: MIT
/// @file
/// One-third-octave bands with the IEC 61260-1 base-10 mid-band frequencies:
///   f_m = 1000 · 10^{x/10} Hz (x integer),  f_lo = f_m · 10^{−1/20},  f_hi = f_m · 10^{+1/20},
/// so that ten bands make a decade and three an (almost exact) octave, 10^{3/10} = 1.995. The nominal
/// labels (125, 160, 200 …) are roundings of f_m; the exact values are used here and written out.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace admitgen::diagnosis {

struct ThirdOctaveBand {
  int index = 0;       ///< x of f_m = 1000 · 10^{x/10}
  double f_lo = 0.0;   ///< lower edge [Hz]
  double f_hi = 0.0;   ///< upper edge [Hz]
  double f_center = 0.0;
  Eigen::Index first = 0;  ///< first data point in [f_lo, f_hi)
  Eigen::Index count = 0;  ///< data points in the band

  bool contains(double f_hz) const { return f_hz >= f_lo && f_hz < f_hi; }
};

/// The band of index x (mid-band frequency 1000 · 10^{x/10}).
ThirdOctaveBand third_octave_band(int x);

/// The bands the data covers: every band whose mid-band frequency lies within [f_min, f_max] of the
/// (ascending) frequencies and that holds at least one point, with its points' index range.
std::vector<ThirdOctaveBand> covered_bands(const Eigen::ArrayXd& f_hz);

}  // namespace admitgen::diagnosis

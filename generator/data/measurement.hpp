// SPDX-License-Identifier: MIT
/// @file
/// Measured (or synthetic) normal-incidence surface admittance: what every command works on.
#pragma once

#include <Eigen/Core>

#include <complex>
#include <string>
#include <vector>

namespace admitgen {

/// Frequencies in Hz, strictly ascending and positive; y the admittance normalised by ρ0c0 in the
/// e^{+jωt} convention. Built only by read_measurement (or by synth), which enforce both.
struct Measurement {
  std::string path;                ///< where it was read from
  std::string sha256;              ///< hash of the file's bytes
  Eigen::ArrayXd f_hz;             ///< ascending, > 0, no duplicates
  Eigen::ArrayXcd y;               ///< normalised admittance at f_hz
  std::vector<std::string> warnings;  ///< non-fatal remarks (e.g. rows were sorted)
  std::string quantity = "admittance";  ///< what the file held: admittance, impedance or reflection
  std::string read_as;  ///< how the file was read: layout, columns, units (docs/reading-data.md)

  Eigen::Index size() const { return f_hz.size(); }
  Eigen::ArrayXd omega() const { return 2.0 * EIGEN_PI * f_hz; }
};

/// Normal-incidence absorption α = 1 − |R|², R = (1 − y)/(1 + y).
Eigen::ArrayXd absorption(const Eigen::ArrayXcd& y);

}  // namespace admitgen

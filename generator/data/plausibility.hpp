// SPDX-License-Identifier: MIT
/// @file
/// Checks that catch a measurement read the wrong way before anything is fitted to it
/// (docs/reading-data.md, "Plausibility checks"): SI values read as normalised (or the reverse),
/// the wrong quantity, an active surface (Re y < 0 over most of the band) and the other time
/// convention (Im y < 0 at the lowest frequencies). Each finding names the option that fixes it.
#pragma once

#include "data/read_options.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen {

/// |y| bounds of a plausible normalised admittance: a reading whose |y| stays below 1/30 (|z| > 30)
/// or above 30 (|z| < 1/30) at every frequency is suspect. An absorber has |z| of order 1 somewhere
/// in its band; a 5 mm layer at 1 kHz still has |z| ≈ cot(kd) ≈ 11, while SI impedance (Pa·s/m) of
/// any absorber stays above ρ0c0·|z|min ≈ 400 Pa·s/m·0.9. A surface with |y| < 1/30 everywhere
/// absorbs α = 4 Re y/|1 + y|² < 4/30 ≈ 0.13 everywhere.
inline constexpr double kPlausibleAdmittanceRatio = 30.0;
/// ρ0c0 assumed in hints when none was given: air at 20 °C, 101.325 kPa (1.204 kg/m³ · 343.2 m/s).
inline constexpr double kTypicalRhoC = 413.3;

/// What the reader did: `values` are the complex numbers of the file (after magnitude/phase
/// conversion and the time convention), `y` the normalised admittance made from them.
struct ReadingForChecks {
  const std::string& path;
  const Eigen::ArrayXd& f_hz;
  const Eigen::ArrayXcd& values;
  const Eigen::ArrayXcd& y;
  Quantity quantity;
  const ReadOptions& options;
};

/// Throws FileError for an implausible reading (or appends a warning when
/// options.plausibility_errors is false, or for findings the user has already confirmed).
void check_plausibility(const ReadingForChecks& r, std::vector<std::string>& warnings);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The simulated admittance `diagnose` compares with the measurement, as a function of frequency:
/// a CSV of simulated admittance (interpolated), a material SPEC, or the multipole of a fit.json.
/// Effects are added to this side (effect_candidates.hpp); those that need the layers (air_gap) need
/// the material.
#pragma once

#include "data/measurement.hpp"
#include "physics/air.hpp"
#include "physics/material.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace admitgen::diagnosis {

class SimulatedSide {
 public:
  /// Tabulated y_sim; evaluated by linear interpolation of Re y and Im y in log f between its
  /// frequencies (no extrapolation: see covers()).
  static SimulatedSide from_table(const Measurement& table, const std::string& description);
  /// A material (layered or multipole), evaluated exactly with `air`.
  static SimulatedSide from_material(const Material& material, const Air& air, const std::string& description);

  /// y_sim at f_hz (ascending, inside the covered range; ENSURE).
  Eigen::ArrayXcd admittance(const Eigen::ArrayXd& f_hz) const;
  /// Whether y_sim is known at f_hz (a table only between its first and last frequency).
  bool covers(double f_hz) const;
  const std::optional<Material>& material() const { return material_; }
  const std::string& description() const { return description_; }

 private:
  std::string description_;
  std::optional<Material> material_;
  std::optional<Air> air_;
  Eigen::ArrayXd table_f_;
  Eigen::ArrayXcd table_y_;
};

}  // namespace admitgen::diagnosis

// SPDX-License-Identifier: MIT
#include "diagnosis/simulated_side.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen::diagnosis {

SimulatedSide SimulatedSide::from_table(const Measurement& table, const std::string& description) {
  ADMITGEN_ENSURE(table.size() >= 2, "a simulated table needs two points, got {}", table.size());
  SimulatedSide s;
  s.description_ = description;
  s.table_f_ = table.f_hz;
  s.table_y_ = table.y;
  return s;
}

SimulatedSide SimulatedSide::from_material(const Material& material, const Air& air, const std::string& description) {
  SimulatedSide s;
  s.description_ = description;
  s.material_ = material;
  s.air_ = air;
  return s;
}

bool SimulatedSide::covers(double f_hz) const {
  if (material_) return f_hz > 0.0;
  return f_hz >= table_f_[0] && f_hz <= table_f_[table_f_.size() - 1];
}

Eigen::ArrayXcd SimulatedSide::admittance(const Eigen::ArrayXd& f_hz) const {
  if (material_) return surface_admittance(*material_, *air_, f_hz);
  Eigen::ArrayXcd y(f_hz.size());
  const double* begin = table_f_.data();
  const double* end = begin + table_f_.size();
  for (Eigen::Index i = 0; i < f_hz.size(); ++i) {
    ADMITGEN_ENSURE(covers(f_hz[i]), "{} Hz is outside the simulated table", f_hz[i]);
    // Segment [j − 1, j] with f_{j−1} ≤ f ≤ f_j; weight t linear in log f.
    const auto j = std::max<std::ptrdiff_t>(1, std::lower_bound(begin, end, f_hz[i]) - begin);
    const double t = std::log(f_hz[i] / table_f_[j - 1]) / std::log(table_f_[j] / table_f_[j - 1]);
    y[i] = (1.0 - t) * table_y_[j - 1] + t * table_y_[j];
  }
  return y;
}

}  // namespace admitgen::diagnosis

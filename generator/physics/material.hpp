// SPDX-License-Identifier: MIT
/// @file
/// A material under test, as `synth` and `diagnose` see it: either a physical layered absorber over a
/// rigid backing, or a surface given directly by a multipole admittance. Built by parse_material_spec
/// (material_spec.hpp); evaluated as the normalised surface admittance y(f), e^{+jωt}.
#pragma once

#include "physics/air.hpp"
#include "model/multipole_surface.hpp"
#include "physics/transfer_matrix.hpp"

#include <Eigen/Core>

#include <variant>

namespace admitgen {

using Material = std::variant<LayeredAbsorber, MultipoleSurface>;

/// y at f_hz, normalised by the ρ0c0 of `air` (a multipole is already normalised and ignores `air`).
Eigen::ArrayXcd surface_admittance(const Material& material, const Air& air, const Eigen::ArrayXd& f_hz);

}  // namespace admitgen

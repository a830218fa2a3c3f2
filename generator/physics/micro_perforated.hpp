// SPDX-License-Identifier: MIT
/// @file
/// Maa's micro-perforated panel (MPP): the series impedance of a thin panel with sub-millimetre holes,
/// placed in a transfer-matrix stack in front of an air cavity (Maa, "Potential of microperforated
/// panel absorber", JASA 104(5) 2861-2866, 1998; docs/materials.md §2.4). e^{+jωt}, normalised by ρ0c0:
///
///   k  = d √(ωρ0/(4η))                                   perforate constant (d = hole diameter)
///   r  = (32 η t/(p ρ0 c0 d²)) [√(1 + k²/32) + (√2/32) k d/t]
///   ωm = (ω t/(p c0)) [1 + 1/√(9 + k²/2) + 0.85 d/t]
///   z_panel = r + jωm
///
/// Over a rigid-backed cavity of depth D this gives Maa's z = r + j(ωm − cot(ωD/c0)). (The
/// 1/√(1 + k²/2) of some implementations is a typo: 9 + k²/2 gives Crandall's 4/3 mass factor.)
#pragma once

#include "physics/air.hpp"

#include <Eigen/Core>

namespace admitgen {

struct MicroPerforatedPanel {
  double hole_diameter;  ///< d [m]
  double thickness;      ///< t [m]
  double perforation;    ///< p, open area ratio in (0, 1)
};

/// z_panel = r + jωm at f_hz, normalised by ρ0c0.
Eigen::ArrayXcd panel_impedance(const MicroPerforatedPanel& panel, const Air& air, const Eigen::ArrayXd& f_hz);

}  // namespace admitgen

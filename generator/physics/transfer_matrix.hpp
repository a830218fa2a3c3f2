// SPDX-License-Identifier: MIT
/// @file
/// Layered absorbers over a rigid backing by transfer matrices (Allard & Atalla, "Propagation of
/// Sound in Porous Media", 2nd ed., ch. 11), e^{+jωt}. Each layer maps pressure and normal velocity
/// at its back face to its front face, [p; v]_front = T [p; v]_back:
///
///   fluid layer (porous or air), thickness h:  T = [ cos k_c h      j Z_c sin k_c h ]
///                                                  [ j sin k_c h/Z_c    cos k_c h   ]
///   thin panel of series impedance Z_p (MPP):  T = [ 1  Z_p ]
///                                                  [ 0   1  ]
///
/// The stack's product T = T_1 T_2 … T_n (front layer first) closed by a rigid backing (v = 0) gives
/// the surface impedance Z_s = T_11/T_21: for one fluid layer, Z_s = −j Z_c cot(k_c h), and for an MPP
/// over an air cavity of depth D, Maa's z = r + jωm − j cot(ωD/c0).
#pragma once

#include "physics/air.hpp"
#include "physics/micro_perforated.hpp"
#include "physics/porous_models.hpp"

#include <Eigen/Core>

#include <variant>
#include <vector>

namespace admitgen {

struct PorousLayer {
  PorousModel model;
  double thickness;  ///< [m]
};

/// A lossless air layer (cavity, gap).
struct AirLayer {
  double thickness;  ///< [m]
};

using Layer = std::variant<PorousLayer, AirLayer, MicroPerforatedPanel>;

/// Layers listed from the one facing the sound to the one on the rigid backing.
struct LayeredAbsorber {
  std::vector<Layer> layers;

  /// Total depth from the exposed face to the backing [m] (panels count as zero).
  double depth() const;
};

/// Normalised surface admittance y = ρ0c0 T_21/T_11 at f_hz (y → 0 as f → 0 for a rigid backing).
/// Written as an admittance so that a panel on the backing (T_21 = 0) gives y = 0, not a division by 0.
Eigen::ArrayXcd surface_admittance(const LayeredAbsorber& absorber, const Air& air, const Eigen::ArrayXd& f_hz);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Rigid-frame porous media as equivalent fluids: the characteristic impedance Z_c and complex
/// wavenumber k_c of a porous layer, in the e^{+jωt} convention (k_c = k' − jk'', k'' > 0: waves
/// decay as they travel). Four models, each as stated in docs/materials.md §2 with its source:
///
///   Delany & Bazley 1970 (empirical, X = ρ0 f/σ, valid 0.01 < X < 1)
///   Miki 1990 (empirical, X = f/σ; positive-real, unlike Delany-Bazley at low X)
///   Johnson-Champoux-Allard (5 parameters: φ, σ, α∞, Λ, Λ')
///   Horoshenkov, Hurrell & Groby 2019 (3 parameters: φ, median pore size s̄, log2 deviation σ_s)
#pragma once

#include "physics/air.hpp"

#include <Eigen/Core>

#include <variant>

namespace admitgen {

struct DelanyBazley {
  double flow_resistivity;  ///< σ [Pa·s/m²]
};

struct Miki {
  double flow_resistivity;  ///< σ [Pa·s/m²]
};

struct JohnsonChampouxAllard {
  double porosity;          ///< φ in (0, 1]
  double flow_resistivity;  ///< σ [Pa·s/m²]
  double tortuosity;        ///< α∞ ≥ 1
  double viscous_length;    ///< Λ [m]
  double thermal_length;    ///< Λ' [m]
};

struct Horoshenkov2019 {
  double porosity;          ///< φ in (0, 1]
  double median_pore_size;  ///< s̄ [m]
  double pore_size_deviation;  ///< σ_s, standard deviation of the log-normal pore size in log2 units
};

using PorousModel = std::variant<DelanyBazley, Miki, JohnsonChampouxAllard, Horoshenkov2019>;

/// Z_c [Pa·s/m] and k_c [1/m] at each frequency.
struct Propagation {
  Eigen::ArrayXcd zc;
  Eigen::ArrayXcd kc;
};

/// Propagation in the porous medium at frequencies f_hz (> 0).
Propagation propagation(const PorousModel& model, const Air& air, const Eigen::ArrayXd& f_hz);

/// Propagation in air itself (lossless): Z_c = ρ0c0, k = ω/c0.
Propagation air_propagation(const Air& air, const Eigen::ArrayXd& f_hz);

/// The Johnson-Champoux-Allard quantities implied by Horoshenkov's three parameters (docs/materials.md
/// §2.3, eqs. 12 and 15 and the JCAL equivalents): α∞ = e^{4ξ}, σ = 8ηα∞ e^{6ξ}/(s̄²φ),
/// Λ = s̄ e^{−5ξ/2}, Λ' = s̄ e^{3ξ/2}, with ξ = (σ_s ln 2)².
struct HoroshenkovDerived {
  double tortuosity;
  double flow_resistivity;
  double viscous_length;
  double thermal_length;
};
HoroshenkovDerived derived_parameters(const Horoshenkov2019& model, const Air& air);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Air as the fluid inside the tube, the pores and the cavities: the constants every material model
/// and the two-microphone chain read. One struct, so a test can pin the constants a paper used.
#pragma once

namespace admitgen {

struct Air {
  double temperature_c;  ///< °C (recorded; the fields below are what the models use)
  double rho0;           ///< density ρ0 [kg/m³]
  double c0;             ///< speed of sound c0 [m/s]
  double eta;            ///< dynamic viscosity η [Pa·s]
  double prandtl;        ///< Prandtl number Pr
  double gamma;          ///< ratio of specific heats γ
  double p0;             ///< static pressure P0 [Pa]

  /// Air at T °C and 101325 Pa, exactly as docs/cli.md ("Effects") states it:
  ///   c = 20.047·√(273.15 + T),  ρ0 = 101325/(287.05·(273.15 + T)),
  /// with η from Sutherland's law η = 1.458e-6·T_K^{3/2}/(T_K + 110.4) (1.813e-5 Pa·s at 20 °C),
  /// Pr = 0.71, γ = 1.4. Throws InputError unless −100 °C < T < 200 °C.
  static Air at_celsius(double temperature_c);

  /// Characteristic impedance of air ρ0c0 [Pa·s/m], the normalisation of z and y.
  double rho_c() const { return rho0 * c0; }
  /// Kinematic viscosity ν = η/ρ0 [m²/s].
  double nu() const { return eta / rho0; }
};

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "physics/porous_models.hpp"

#include <cmath>
#include <complex>

namespace admitgen {
namespace {

using cd = std::complex<double>;
constexpr cd kJ{0.0, 1.0};

Eigen::ArrayXd angular(const Eigen::ArrayXd& f_hz) { return 2.0 * EIGEN_PI * f_hz; }

/// Z_c = √(ρ K), k_c = ω √(ρ/K) for an equivalent fluid of effective density ρ and bulk modulus K.
/// Principal square roots give Re Z_c > 0 and Im k_c < 0 (e^{+jωt}: Im ρ < 0, Im K > 0).
Propagation from_density_and_modulus(const Eigen::ArrayXcd& rho, const Eigen::ArrayXcd& bulk,
                                     const Eigen::ArrayXd& omega) {
  return {(rho * bulk).sqrt(), omega * (rho / bulk).sqrt()};
}

/// Delany & Bazley 1970, e^{+jωt}, X = ρ0 f/σ:
///   Z_c = ρ0c0 [1 + 0.0571 X^−0.754 − j 0.087 X^−0.732]
///   k_c = (ω/c0) [1 + 0.0978 X^−0.700 − j 0.189 X^−0.595]
Propagation evaluate(const DelanyBazley& m, const Air& air, const Eigen::ArrayXd& f) {
  const Eigen::ArrayXd x = air.rho0 * f / m.flow_resistivity;
  Propagation p{Eigen::ArrayXcd(f.size()), Eigen::ArrayXcd(f.size())};
  p.zc.real() = air.rho_c() * (1.0 + 0.0571 * x.pow(-0.754));
  p.zc.imag() = air.rho_c() * (-0.087 * x.pow(-0.732));
  const Eigen::ArrayXd k0 = angular(f) / air.c0;
  p.kc.real() = k0 * (1.0 + 0.0978 * x.pow(-0.700));
  p.kc.imag() = k0 * (-0.189 * x.pow(-0.595));
  return p;
}

/// Miki 1990, e^{+jωt}, X = f/σ (not ρ0 f/σ):
///   Z_c = ρ0c0 [1 + 0.070 X^−0.632 − j 0.107 X^−0.632]
///   k_c = (ω/c0) [1 + 0.109 X^−0.618 − j 0.160 X^−0.618]
Propagation evaluate(const Miki& m, const Air& air, const Eigen::ArrayXd& f) {
  const Eigen::ArrayXd xz = (f / m.flow_resistivity).pow(-0.632);
  const Eigen::ArrayXd xk = (f / m.flow_resistivity).pow(-0.618);
  Propagation p{Eigen::ArrayXcd(f.size()), Eigen::ArrayXcd(f.size())};
  p.zc.real() = air.rho_c() * (1.0 + 0.070 * xz);
  p.zc.imag() = air.rho_c() * (-0.107 * xz);
  const Eigen::ArrayXd k0 = angular(f) / air.c0;
  p.kc.real() = k0 * (1.0 + 0.109 * xk);
  p.kc.imag() = k0 * (-0.160 * xk);
  return p;
}

/// Johnson-Champoux-Allard, e^{+jωt} (docs/materials.md §2.2):
///   ρ_eq = (α∞ρ0/φ) [1 + (σφ/(jωρ0α∞)) √(1 + j 4α∞² η ρ0 ω/(σ² Λ² φ²))]
///   K_eq = (γP0/φ) / [γ − (γ−1) (1 + (8η/(jω Pr Λ'² ρ0)) √(1 + jωρ0 Pr Λ'²/(16η)))^−1]
Propagation evaluate(const JohnsonChampouxAllard& m, const Air& air, const Eigen::ArrayXd& f) {
  const Eigen::ArrayXd omega = angular(f);
  const double phi = m.porosity, sigma = m.flow_resistivity, tort = m.tortuosity;
  const double lv = m.viscous_length, lt = m.thermal_length;
  Eigen::ArrayXcd rho(f.size()), bulk(f.size());
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    const double w = omega[i];
    const cd visc = std::sqrt(1.0 + kJ * 4.0 * tort * tort * air.eta * air.rho0 * w / (sigma * sigma * lv * lv * phi * phi));
    rho[i] = (tort * air.rho0 / phi) * (1.0 + sigma * phi / (kJ * w * air.rho0 * tort) * visc);
    const cd therm = std::sqrt(1.0 + kJ * w * air.rho0 * air.prandtl * lt * lt / (16.0 * air.eta));
    const cd inner = 1.0 + 8.0 * air.eta / (kJ * w * air.prandtl * lt * lt * air.rho0) * therm;
    bulk[i] = (air.gamma * air.p0 / phi) / (air.gamma - (air.gamma - 1.0) / inner);
  }
  return from_density_and_modulus(rho, bulk, omega);
}

/// Horoshenkov, Hurrell & Groby 2019 (JASA 145(4) 2512, eqs. 12-19), rewritten for e^{+jωt} by
/// replacing −iω with +jω (the conjugate of the paper's e^{−iωt} form):
///   ξ = (σ_s ln 2)², α∞ = e^{4ξ}, σ = 8ηα∞ e^{6ξ}/(s̄²φ), σ' = 8ηα∞ e^{−6ξ}/(s̄²φ)
///   ε_ρ = √(jωρ0α∞/(φσ)),  ε_C = √(jωρ0 Pr α∞/(φσ'))
///   θ_ρ1 = 1/3, θ_ρ2 = e^{−ξ/2}/√2, θ_ρ3 = θ_ρ1/θ_ρ2;  θ_C1 = 1/3, θ_C2 = e^{3ξ/2}/√2, θ_C3 = θ_C1/θ_C2
///   F(ε) = (1 + θ3 ε + θ1 ε²)/(1 + θ3 ε)
///   ρ = (ρ0α∞/φ)(1 + ε_ρ^−2 F_ρ),  C = (φ/(γP0)) [γ − (γ−1)/(1 + ε_C^−2 F_C)],  K = 1/C
Propagation evaluate(const Horoshenkov2019& m, const Air& air, const Eigen::ArrayXd& f) {
  const Eigen::ArrayXd omega = angular(f);
  const double xi = std::pow(m.pore_size_deviation * std::log(2.0), 2);
  const double phi = m.porosity;
  const HoroshenkovDerived jcal = derived_parameters(m, air);
  const double tort = jcal.tortuosity, sigma = jcal.flow_resistivity;
  const double sigma_th = sigma * std::exp(-12.0 * xi);  // σ' = σ e^{−12ξ} (eqs. 15, 18)
  const double t1 = 1.0 / 3.0;
  const double tr3 = t1 / (std::exp(-xi / 2.0) / std::sqrt(2.0));
  const double tc3 = t1 / (std::exp(3.0 * xi / 2.0) / std::sqrt(2.0));
  const auto pade = [t1](cd eps, double t3) { return (1.0 + t3 * eps + t1 * eps * eps) / (1.0 + t3 * eps); };
  Eigen::ArrayXcd rho(f.size()), bulk(f.size());
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    const double w = omega[i];
    const cd eps_rho = std::sqrt(kJ * w * air.rho0 * tort / (phi * sigma));
    const cd eps_c = std::sqrt(kJ * w * air.rho0 * air.prandtl * tort / (phi * sigma_th));
    rho[i] = (air.rho0 * tort / phi) * (1.0 + pade(eps_rho, tr3) / (eps_rho * eps_rho));
    const cd compliance =
        (phi / (air.gamma * air.p0)) * (air.gamma - (air.gamma - 1.0) / (1.0 + pade(eps_c, tc3) / (eps_c * eps_c)));
    bulk[i] = 1.0 / compliance;
  }
  return from_density_and_modulus(rho, bulk, omega);
}

}  // namespace

Propagation propagation(const PorousModel& model, const Air& air, const Eigen::ArrayXd& f_hz) {
  return std::visit([&](const auto& m) { return evaluate(m, air, f_hz); }, model);
}

Propagation air_propagation(const Air& air, const Eigen::ArrayXd& f_hz) {
  return {Eigen::ArrayXcd::Constant(f_hz.size(), air.rho_c()), (angular(f_hz) / air.c0).cast<cd>()};
}

HoroshenkovDerived derived_parameters(const Horoshenkov2019& m, const Air& air) {
  const double xi = std::pow(m.pore_size_deviation * std::log(2.0), 2);
  const double tort = std::exp(4.0 * xi);
  return {tort,
          8.0 * air.eta * tort / (m.median_pore_size * m.median_pore_size * m.porosity) * std::exp(6.0 * xi),
          m.median_pore_size * std::exp(-2.5 * xi), m.median_pore_size * std::exp(1.5 * xi)};
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The measurement and mounting effects of docs/cli.md ("Effects": one vocabulary for `synth --effect`
/// and `diagnose`), by their documented names and parameters, written `NAME` or `NAME:k=v,k=v`:
///
/// | name | parameters | acts on |
/// |---|---|---|
/// | `none` | — | nothing |
/// | `reference_plane` | `delta_m` | R' = R e^{−2jkδ} (the chain with both mics δ further) |
/// | `mic_spacing` | `delta_m` | chain: near mic at x1 − s − δ, processed with s |
/// | `mic_mismatch` | `gain`, `phase_deg` | chain: H12' = H12 (1 + gain) e^{jφ} |
/// | `temperature` | `delta_k` | chain at T + ΔT, y scaled by ρ0c0(T+ΔT)/ρ0c0(T), processed at T |
/// | `tube_losses` | — | chain: true k lossy (tube diameter d), processed lossless |
/// | `edge_gap` | `width_m`, `depth_m` | y' = (1 − ε) y + ε y_slit, ε = 1 − (1 − 2w/d)² |
/// | `frame_resonance` | `f0_hz`, `q`, `y_peak` | y' = y + y_peak/(1 + jq(f/f0 − f0/f)) |
/// | `fractional_order` | `c_plus`, `c_minus`, `f_ref_hz` | y' = y + c₊(jω/ω_r)^{1/2} + c₋(jω/ω_r)^{−1/2} |
/// | `air_gap` | `gap_m` | an air layer between a layered material and its rigid backing |
/// | `heteroscedastic_noise` | `scale` | noise std σ_i = σ √(1 + (scale/|sin ks|)²) |
///
/// Lengths accept units (`delta_m=1mm`). Every listed parameter is required; an unknown one is an error.
/// Each effect is a type of its own, so an effect without its parameters cannot exist.
#pragma once

#include "physics/air.hpp"

#include <Eigen/Core>

#include <complex>
#include <string>
#include <variant>
#include <vector>

namespace admitgen {

struct NoEffect {};
struct ReferencePlane {
  double delta_m;
};
struct MicSpacing {
  double delta_m;
};
struct MicMismatch {
  double gain;       ///< > −1
  double phase_deg;
};
struct TemperatureOffset {
  double delta_k;
};
struct TubeLosses {};
struct EdgeGap {
  double width_m;  ///< w, 0 < w < d/2
  double depth_m;  ///< slit length h (usually the sample thickness)
};
struct FrameResonance {
  double f0_hz;   ///< > 0
  double q;       ///< > 0
  double y_peak;  ///< added conductance at f0 (passive for ≥ 0)
};
struct FractionalOrder {
  double c_plus;   ///< passive for ≥ 0
  double c_minus;  ///< passive for ≥ 0
  double f_ref_hz;  ///< > 0
};
struct AirGap {
  double gap_m;  ///< > 0
};
struct HeteroscedasticNoise {
  double scale;  ///< ≥ 0
};

using Effect = std::variant<NoEffect, ReferencePlane, MicSpacing, MicMismatch, TemperatureOffset, TubeLosses, EdgeGap,
                            FrameResonance, FractionalOrder, AirGap, HeteroscedasticNoise>;

/// Parses `NAME` or `NAME:k=v,...`; throws InputError naming the effect and what is wrong.
Effect parse_effect(const std::string& text);
/// The documented name, e.g. "frame_resonance".
std::string effect_name(const Effect& effect);
/// Canonical text `NAME:k=v,...` (shortest round-trip numbers, SI units) that parse_effect reads back.
std::string to_string(const Effect& effect);

/// What an effect needs from the tube setup.
enum class GeometryNeed {
  none,      ///< none, reference_plane (closed form), frame_resonance, fractional_order, air_gap
  diameter,  ///< edge_gap (ε uses d)
  full,      ///< mic_spacing, mic_mismatch, temperature, tube_losses, heteroscedastic_noise
};
GeometryNeed geometry_need(const Effect& effect);

/// Closed forms acting on y at f_hz (normalised by `air`'s ρ0c0).
Eigen::ArrayXcd apply_frame_resonance(const FrameResonance& e, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y);
Eigen::ArrayXcd apply_fractional_order(const FractionalOrder& e, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y);
/// R' = R e^{−2jkδ}, k = ω/c0.
Eigen::ArrayXcd apply_reference_plane(const ReferencePlane& e, const Air& air, const Eigen::ArrayXd& f_hz,
                                      const Eigen::ArrayXcd& y);
/// y' = (1 − ε) y + ε y_slit with ε = 1 − (1 − 2w/d)², d the tube diameter.
Eigen::ArrayXcd apply_edge_gap(const EdgeGap& e, double tube_diameter_m, const Air& air, const Eigen::ArrayXd& f_hz,
                               const Eigen::ArrayXcd& y);

/// Normalised admittance of a rigid-backed slit of width w and depth h (docs/physics.md §5.1 f), with the
/// low-reduced-frequency slit fluid:
///   ρ_e = ρ0/[1 − tanh(σ_v)/σ_v],  K_e = γP0/[1 + (γ−1) tanh(σ_t)/σ_t],
///   σ_v = (w/2)√(jω/ν),  σ_t = (w/2)√(jω Pr/ν),
///   Z_slit = −j √(ρ_e K_e) cot(ω √(ρ_e/K_e) h),  y_slit = ρ0c0/Z_slit.
Eigen::ArrayXcd slit_admittance(double width_m, double depth_m, const Air& air, const Eigen::ArrayXd& f_hz);

/// slit_admittance and apply_edge_gap on one frequency grid, with what does not depend on the slit
/// (ω, √(jω/ν), √(jω Pr/ν)) computed once (for `diagnose`). Results equal the free functions' exactly.
class SlitModel {
 public:
  SlitModel(const Air& air, const Eigen::ArrayXd& f_hz);
  Eigen::ArrayXcd admittance(double width_m, double depth_m) const;
  /// apply_edge_gap(e, tube_diameter_m, air, f_hz, y).
  Eigen::ArrayXcd edge_gap(const EdgeGap& e, double tube_diameter_m, const Eigen::ArrayXcd& y) const;

 protected:
  /// y_slit = j (ρ0c0/Z_c) tan(ω S h): Z_c = √(ρ_e K_e) and the slowness S = √(ρ_e/K_e) = Z_c/K_e depend on
  /// the width and the frequency only through x_v = (w/2)√(ω/2ν) (and x_t = x_v √Pr).
  struct Fluid {
    std::complex<double> characteristic;  ///< Z_c
    std::complex<double> slowness;        ///< S
  };
  Fluid fluid(double x_v, double x_t) const;
  /// The admittance from the fluid at point i (ρ0c0 · j tan(ω S h) / Z_c, as admittance() computes it).
  std::complex<double> admittance_from(const Fluid& fluid, Eigen::Index i, double depth_m) const;

  Air air_;
  Eigen::ArrayXd omega_;
  Eigen::ArrayXd half_root_v_, half_root_t_;  ///< √(ω/2ν), √(ω Pr/2ν): √(jω/ν) = √(ω/2ν)(1 + j)
};

/// SlitModel with the fluid tabulated (for `diagnose`, which evaluates thousands of slits on one grid).
/// U = (ρ0c0/Z_c)(1 + 1/x_v) and V = S x_v/(1 + x_v) are smooth and bounded in s = ln x_v (Z_c ∝ 1/x_v
/// in the viscous limit, → ρ0c0 for wide slits), tabulated on kSlitTableNodes equally spaced s over
/// x_v ∈ [kSlitTableLow, kSlitTableHigh] and read by 4-point Lagrange interpolation (error ≤ 0.023 h⁴
/// max|d⁴/ds⁴|, h the node step); outside that range the fluid is computed as SlitModel does. What is
/// left per point is one complex tan. The admittance agrees with SlitModel's to the tolerance stated and
/// tested in tests/physics/test_effects.cpp (1e-9 relative over the edge_gap prior of `diagnose` and
/// 10 Hz-12 kHz).
class TabulatedSlitModel : public SlitModel {
 public:
  static constexpr double kSlitTableLow = 1e-2, kSlitTableHigh = 1e2;
  static constexpr int kSlitTableNodes = 4096;

  TabulatedSlitModel(const Air& air, const Eigen::ArrayXd& f_hz);
  Eigen::ArrayXcd admittance(double width_m, double depth_m) const;
  Eigen::ArrayXcd edge_gap(const EdgeGap& e, double tube_diameter_m, const Eigen::ArrayXcd& y) const;

 private:
  double step_;                   ///< h in s = ln x_v
  Eigen::ArrayXcd u_, v_;         ///< at s_k = ln kSlitTableLow + (k − 1) h, k = 0 … kSlitTableNodes + 2
  Eigen::ArrayXd log_half_root_v_;  ///< ln √(ω/2ν), so s = ln(w/2) + this
};

}  // namespace admitgen

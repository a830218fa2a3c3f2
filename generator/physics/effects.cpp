// SPDX-License-Identifier: MIT
#include "physics/effects.hpp"

#include "core/errors.hpp"
#include "physics/overloaded.hpp"
#include "physics/parameter_list.hpp"
#include "physics/two_microphone.hpp"

#include <fmt/format.h>

#include <cmath>
#include <complex>

namespace admitgen {
namespace {

using cd = std::complex<double>;
constexpr cd kJ{0.0, 1.0};

constexpr const char* kNames =
    "none, reference_plane, mic_spacing, mic_mismatch, temperature, tube_losses, edge_gap, frame_resonance, "
    "fractional_order, air_gap, heteroscedastic_noise";

Effect parse_named(const std::string& name, ParameterList& p) {
  if (name == "none") return NoEffect{};
  if (name == "reference_plane") return ReferencePlane{p.number("delta_m", Dimension::length)};
  if (name == "mic_spacing") return MicSpacing{p.number("delta_m", Dimension::length)};
  if (name == "mic_mismatch") {
    const MicMismatch e{p.number("gain"), p.number("phase_deg")};
    if (!(e.gain > -1.0)) throw InputError(p.error(fmt::format("'gain' must exceed -1 (got {})", e.gain)));
    return e;
  }
  if (name == "temperature") return TemperatureOffset{p.number("delta_k")};
  if (name == "tube_losses") return TubeLosses{};
  if (name == "edge_gap") return EdgeGap{p.positive("width_m", Dimension::length), p.positive("depth_m", Dimension::length)};
  if (name == "frame_resonance") return FrameResonance{p.positive("f0_hz"), p.positive("q"), p.number("y_peak")};
  if (name == "fractional_order") return FractionalOrder{p.number("c_plus"), p.number("c_minus"), p.positive("f_ref_hz")};
  if (name == "air_gap") return AirGap{p.positive("gap_m", Dimension::length)};
  if (name == "heteroscedastic_noise") {
    const HeteroscedasticNoise e{p.number("scale")};
    if (!(e.scale >= 0.0)) throw InputError(p.error(fmt::format("'scale' must be >= 0 (got {})", e.scale)));
    return e;
  }
  throw InputError(p.error(fmt::format("unknown effect '{}' (known: {})", name, kNames)));
}

}  // namespace

Effect parse_effect(const std::string& text) {
  const auto colon = text.find(':');
  const std::string name(trim(std::string_view(text).substr(0, colon)));
  ParameterList p(fmt::format("effect '{}'", text), colon == std::string::npos ? std::string_view() : std::string_view(text).substr(colon + 1));
  const Effect effect = parse_named(name, p);
  p.finish();
  return effect;
}

std::string effect_name(const Effect& effect) {
  return std::visit(Overloaded{[](const NoEffect&) { return "none"; },
                               [](const ReferencePlane&) { return "reference_plane"; },
                               [](const MicSpacing&) { return "mic_spacing"; },
                               [](const MicMismatch&) { return "mic_mismatch"; },
                               [](const TemperatureOffset&) { return "temperature"; },
                               [](const TubeLosses&) { return "tube_losses"; },
                               [](const EdgeGap&) { return "edge_gap"; },
                               [](const FrameResonance&) { return "frame_resonance"; },
                               [](const FractionalOrder&) { return "fractional_order"; },
                               [](const AirGap&) { return "air_gap"; },
                               [](const HeteroscedasticNoise&) { return "heteroscedastic_noise"; }},
                    effect);
}

std::string to_string(const Effect& effect) {
  const std::string params = std::visit(
      Overloaded{[](const NoEffect&) { return std::string(); },
                 [](const ReferencePlane& e) { return fmt::format("delta_m={}", e.delta_m); },
                 [](const MicSpacing& e) { return fmt::format("delta_m={}", e.delta_m); },
                 [](const MicMismatch& e) { return fmt::format("gain={},phase_deg={}", e.gain, e.phase_deg); },
                 [](const TemperatureOffset& e) { return fmt::format("delta_k={}", e.delta_k); },
                 [](const TubeLosses&) { return std::string(); },
                 [](const EdgeGap& e) { return fmt::format("width_m={},depth_m={}", e.width_m, e.depth_m); },
                 [](const FrameResonance& e) { return fmt::format("f0_hz={},q={},y_peak={}", e.f0_hz, e.q, e.y_peak); },
                 [](const FractionalOrder& e) {
                   return fmt::format("c_plus={},c_minus={},f_ref_hz={}", e.c_plus, e.c_minus, e.f_ref_hz);
                 },
                 [](const AirGap& e) { return fmt::format("gap_m={}", e.gap_m); },
                 [](const HeteroscedasticNoise& e) { return fmt::format("scale={}", e.scale); }},
      effect);
  return params.empty() ? effect_name(effect) : effect_name(effect) + ":" + params;
}

GeometryNeed geometry_need(const Effect& effect) {
  return std::visit(Overloaded{[](const MicSpacing&) { return GeometryNeed::full; },
                               [](const MicMismatch&) { return GeometryNeed::full; },
                               [](const TemperatureOffset&) { return GeometryNeed::full; },
                               [](const TubeLosses&) { return GeometryNeed::full; },
                               [](const HeteroscedasticNoise&) { return GeometryNeed::full; },
                               [](const EdgeGap&) { return GeometryNeed::diameter; },
                               [](const auto&) { return GeometryNeed::none; }},
                    effect);
}

Eigen::ArrayXcd apply_frame_resonance(const FrameResonance& e, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y) {
  const Eigen::ArrayXd detuning = e.q * (f_hz / e.f0_hz - e.f0_hz / f_hz);
  return y + e.y_peak / (1.0 + kJ * detuning.cast<cd>());
}

Eigen::ArrayXcd apply_fractional_order(const FractionalOrder& e, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y) {
  // (jω/ω_r)^{±1/2} = (f/f_ref)^{±1/2} e^{±jπ/4}
  const Eigen::ArrayXd ratio = (f_hz / e.f_ref_hz).sqrt();
  const cd up = std::polar(1.0, static_cast<double>(EIGEN_PI) / 4.0), down = std::conj(up);
  return y + (e.c_plus * up) * ratio.cast<cd>() + (e.c_minus * down) * ratio.inverse().cast<cd>();
}

Eigen::ArrayXcd apply_reference_plane(const ReferencePlane& e, const Air& air, const Eigen::ArrayXd& f_hz,
                                      const Eigen::ArrayXcd& y) {
  const Eigen::ArrayXcd k = lossless_wavenumber(air, f_hz);
  return admittance_from_reflection(reflection_from_admittance(y) * (-2.0 * kJ * e.delta_m * k).exp());
}

Eigen::ArrayXcd slit_admittance(double width_m, double depth_m, const Air& air, const Eigen::ArrayXd& f_hz) {
  return SlitModel(air, f_hz).admittance(width_m, depth_m);
}

Eigen::ArrayXcd apply_edge_gap(const EdgeGap& e, double tube_diameter_m, const Air& air, const Eigen::ArrayXd& f_hz,
                               const Eigen::ArrayXcd& y) {
  return SlitModel(air, f_hz).edge_gap(e, tube_diameter_m, y);
}

SlitModel::SlitModel(const Air& air, const Eigen::ArrayXd& f_hz)
    : air_(air), omega_(f_hz.size()), root_v_(f_hz.size()), root_t_(f_hz.size()) {
  for (Eigen::Index i = 0; i < f_hz.size(); ++i) {
    omega_[i] = 2.0 * EIGEN_PI * f_hz[i];
    root_v_[i] = std::sqrt(kJ * omega_[i] / air.nu());
    root_t_[i] = std::sqrt(kJ * omega_[i] * air.prandtl / air.nu());
  }
}

Eigen::ArrayXcd SlitModel::admittance(double width_m, double depth_m) const {
  Eigen::ArrayXcd y(omega_.size());
  for (Eigen::Index i = 0; i < omega_.size(); ++i) {
    const cd sv = (width_m / 2.0) * root_v_[i];
    const cd st = (width_m / 2.0) * root_t_[i];
    const cd rho = air_.rho0 / (1.0 - std::tanh(sv) / sv);
    const cd bulk = air_.gamma * air_.p0 / (1.0 + (air_.gamma - 1.0) * std::tanh(st) / st);
    const cd zc = std::sqrt(rho * bulk), k = omega_[i] * std::sqrt(rho / bulk);
    y[i] = air_.rho_c() * kJ * std::tan(k * depth_m) / zc;  // ρ0c0/(−j Z_c cot kh)
  }
  return y;
}

Eigen::ArrayXcd SlitModel::edge_gap(const EdgeGap& e, double tube_diameter_m, const Eigen::ArrayXcd& y) const {
  if (!(2.0 * e.width_m < tube_diameter_m))
    throw InputError(fmt::format("edge_gap width_m {} m must be less than half the tube diameter {} m", e.width_m,
                                 tube_diameter_m));
  const double eps = 1.0 - std::pow(1.0 - 2.0 * e.width_m / tube_diameter_m, 2);
  return (1.0 - eps) * y + eps * admittance(e.width_m, e.depth_m);
}

}  // namespace admitgen

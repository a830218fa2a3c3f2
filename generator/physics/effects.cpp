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

/// a/b without the library's scaled division (__divdc3): |b| here lies far from overflow and underflow
/// (the slit's denominators below are between about 1e-12 and 4 in modulus).
cd divide(cd a, cd b) {
  const double inv = 1.0 / std::norm(b);
  return {(a.real() * b.real() + a.imag() * b.imag()) * inv, (a.imag() * b.real() - a.real() * b.imag()) * inv};
}

/// (1 − t)/(1 + t) for t = e^{−2x}(cos 2y − j sin 2y), x ≥ 0: the common core of tanh(x + jy) and
/// tan(y − jx). With s, c = sin y, cos y: 1 − e^{−2x} cos 2y = −expm1(−2x) cos 2y + 2s² keeps full relative
/// precision for small arguments, and |t| ≤ 1 keeps wide slits and lossy columns free of overflow.
cd one_minus_over_one_plus(double x, double y) {
  const double m = std::expm1(-2.0 * x), decay = 1.0 + m, s = std::sin(y), c = std::cos(y);
  const double sin2 = 2.0 * s * c, cos2 = 1.0 - 2.0 * s * s;
  return divide({-m * cos2 + 2.0 * s * s, decay * sin2}, {1.0 + decay * cos2, -decay * sin2});
}

/// tanh(z)/z for z = x(1 + j), x ≥ 0: the slit argument σ = (w/2)√(jω/ν) = x(1 + j) with
/// x = (w/2)√(ω/2ν); tanh z = (1 − e^{−2z})/(1 + e^{−2z}).
cd tanh_over_argument_diagonal(double x) {
  if (x == 0.0) return 1.0;
  return divide(one_minus_over_one_plus(x, x), cd{x, x});
}

/// tan w = −j (1 − e^{−2jw})/(1 + e^{−2jw}) for Im w ≤ 0 (a wave decaying along the slit, e^{+jωt}); the
/// mirror tan w = conj tan(conj w) covers Im w > 0.
cd tan_complex(cd w) {
  if (w.imag() > 0.0) return std::conj(tan_complex(std::conj(w)));
  const cd ratio = one_minus_over_one_plus(-w.imag(), w.real());
  return {ratio.imag(), -ratio.real()};
}

/// ε = 1 − (1 − 2w/d)², the fraction of the tube's cross-section the slit takes.
double edge_gap_fraction(const EdgeGap& e, double tube_diameter_m) {
  if (!(2.0 * e.width_m < tube_diameter_m))
    throw InputError(fmt::format("edge_gap width_m {} m must be less than half the tube diameter {} m", e.width_m,
                                 tube_diameter_m));
  return 1.0 - std::pow(1.0 - 2.0 * e.width_m / tube_diameter_m, 2);
}

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
    : air_(air), omega_(2.0 * EIGEN_PI * f_hz), half_root_v_((omega_ / (2.0 * air.nu())).sqrt()),
      half_root_t_(half_root_v_ * std::sqrt(air.prandtl)) {}

SlitModel::Fluid SlitModel::fluid(double x_v, double x_t) const {
  // σ_v = (w/2)√(jω/ν) = x_v(1 + j), likewise σ_t = x_t(1 + j) with x_t = (w/2)√(ω Pr/2ν).
  const double gamma_p0 = air_.gamma * air_.p0;
  const cd fv = tanh_over_argument_diagonal(x_v);
  const cd ft = tanh_over_argument_diagonal(x_t);
  const cd rho = divide(air_.rho0, 1.0 - fv);
  const cd bulk = divide(gamma_p0, 1.0 + (air_.gamma - 1.0) * ft);
  const cd zc = std::sqrt(rho * bulk);
  return {zc, divide(zc, bulk)};  // √(ρ/K) = √(ρK)/K
}

cd SlitModel::admittance_from(const Fluid& fluid, Eigen::Index i, double depth_m) const {
  const cd k = omega_[i] * fluid.slowness;
  return divide(air_.rho_c() * kJ * tan_complex(k * depth_m), fluid.characteristic);  // ρ0c0/(−j Z_c cot kh)
}

Eigen::ArrayXcd SlitModel::admittance(double width_m, double depth_m) const {
  Eigen::ArrayXcd y(omega_.size());
  for (Eigen::Index i = 0; i < omega_.size(); ++i)
    y[i] = admittance_from(fluid(0.5 * width_m * half_root_v_[i], 0.5 * width_m * half_root_t_[i]), i, depth_m);
  return y;
}

Eigen::ArrayXcd SlitModel::edge_gap(const EdgeGap& e, double tube_diameter_m, const Eigen::ArrayXcd& y) const {
  const double eps = edge_gap_fraction(e, tube_diameter_m);
  return (1.0 - eps) * y + eps * admittance(e.width_m, e.depth_m);
}

TabulatedSlitModel::TabulatedSlitModel(const Air& air, const Eigen::ArrayXd& f_hz)
    : SlitModel(air, f_hz),
      step_(std::log(kSlitTableHigh / kSlitTableLow) / (kSlitTableNodes - 1)),
      u_(kSlitTableNodes + 2),
      v_(kSlitTableNodes + 2),
      log_half_root_v_(half_root_v_.log()) {
  for (Eigen::Index k = 0; k < u_.size(); ++k) {
    const double x = kSlitTableLow * std::exp(static_cast<double>(k - 1) * step_);
    const Fluid f = fluid(x, x * std::sqrt(air_.prandtl));
    u_[k] = divide(air_.rho_c(), f.characteristic) * (1.0 + 1.0 / x);
    v_[k] = f.slowness * (x / (1.0 + x));
  }
}

Eigen::ArrayXcd TabulatedSlitModel::admittance(double width_m, double depth_m) const {
  const double s0 = std::log(0.5 * width_m) - std::log(kSlitTableLow);
  Eigen::ArrayXcd y(omega_.size());
  for (Eigen::Index i = 0; i < omega_.size(); ++i) {
    const double q = (s0 + log_half_root_v_[i]) / step_;  // s in steps from the first inner node
    if (!(q >= 0.0 && q < kSlitTableNodes - 1)) {
      y[i] = admittance_from(fluid(0.5 * width_m * half_root_v_[i], 0.5 * width_m * half_root_t_[i]), i, depth_m);
      continue;
    }
    const double floor_q = std::floor(q), t = q - floor_q;
    const Eigen::Index k = static_cast<Eigen::Index>(floor_q) + 1;  // node at or below s; k − 1 … k + 2 used
    // 4-point Lagrange weights on nodes −1, 0, 1, 2 at t ∈ [0, 1).
    const double a = t + 1.0, b = t, c = t - 1.0, d = t - 2.0;
    const double w0 = -b * c * d / 6.0, w1 = a * c * d / 2.0, w2 = -a * b * d / 2.0, w3 = a * b * c / 6.0;
    const cd u = w0 * u_[k - 1] + w1 * u_[k] + w2 * u_[k + 1] + w3 * u_[k + 2];
    const cd v = w0 * v_[k - 1] + w1 * v_[k] + w2 * v_[k + 1] + w3 * v_[k + 2];
    const double x = 0.5 * width_m * half_root_v_[i], ratio = x / (1.0 + x);
    y[i] = kJ * (u * ratio) * tan_complex(omega_[i] * (v / ratio) * depth_m);
  }
  return y;
}

Eigen::ArrayXcd TabulatedSlitModel::edge_gap(const EdgeGap& e, double tube_diameter_m, const Eigen::ArrayXcd& y) const {
  const double eps = edge_gap_fraction(e, tube_diameter_m);
  return (1.0 - eps) * y + eps * admittance(e.width_m, e.depth_m);
}

}  // namespace admitgen

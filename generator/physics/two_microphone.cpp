// SPDX-License-Identifier: MIT
#include "physics/two_microphone.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace admitgen {
namespace {

using cd = std::complex<double>;
constexpr cd kJ{0.0, 1.0};

}  // namespace

TubeGeometry::TubeGeometry(double diameter_m, double spacing_m, double mic1_distance_m)
    : d_(diameter_m), s_(spacing_m), x1_(mic1_distance_m) {
  const auto check = [](double v, const std::string& option) {
    if (!(std::isfinite(v) && v > 0.0)) throw InputError(fmt::format("{} must be a positive length in metres (got {})", option, v));
  };
  check(d_, setting("tube.diameter_m"));
  check(s_, setting("tube.spacing_m"));
  check(x1_, setting("tube.mic1_distance_m"));
  if (!(s_ < x1_))
    throw InputError(fmt::format("{} {} m must be less than {} {} m (x1 is the sample to the farther microphone, "
                                 "so the near one sits at x1 - s > 0)",
                                 setting("tube.spacing_m"), s_, setting("tube.mic1_distance_m"), x1_));
}

Eigen::ArrayXcd reflection_from_admittance(const Eigen::ArrayXcd& y) { return (1.0 - y) / (1.0 + y); }
Eigen::ArrayXcd admittance_from_reflection(const Eigen::ArrayXcd& r) { return (1.0 - r) / (1.0 + r); }

Eigen::ArrayXcd transfer_function(const Eigen::ArrayXcd& r, const Eigen::ArrayXcd& k, double x1, double x2) {
  const auto p = [&](double x) -> Eigen::ArrayXcd { return (kJ * x * k).exp() + r * (-kJ * x * k).exp(); };
  return p(x2) / p(x1);
}

Eigen::ArrayXcd reflection_from_transfer(const Eigen::ArrayXcd& h12, const Eigen::ArrayXcd& k, double x1, double s) {
  const Eigen::ArrayXcd h_i = (-kJ * s * k).exp(), h_r = (kJ * s * k).exp();
  return (2.0 * kJ * x1 * k).exp() * (h12 - h_i) / (h_r - h12);
}

Eigen::ArrayXcd lossless_wavenumber(const Air& air, const Eigen::ArrayXd& f_hz) {
  return (2.0 * EIGEN_PI * f_hz / air.c0).cast<cd>();
}

Eigen::ArrayXcd lossy_wavenumber(const Air& air, const Eigen::ArrayXd& f_hz, double diameter_m) {
  const Eigen::ArrayXd attenuation = 0.0194 * f_hz.sqrt() / (air.c0 * diameter_m);
  return lossless_wavenumber(air, f_hz) + cd(1.0, -1.0) * attenuation.cast<cd>();
}

Eigen::ArrayXcd measure_through_chain(const Eigen::ArrayXcd& y_true, const Eigen::ArrayXd& f_hz, const Air& air,
                                      const TubeGeometry& tube, const ChainDeviation& dev) {
  return TwoMicrophoneChain(y_true, f_hz, air, tube).measure(dev);
}

Eigen::ArrayXcd correct_through_chain(const Eigen::ArrayXcd& y_measured, const Eigen::ArrayXd& f_hz, const Air& air,
                                      const TubeGeometry& tube, const ChainDeviation& dev) {
  const double x1 = tube.mic1_distance(), x1_true = x1 + dev.reference_plane_m;
  const double s_true = tube.spacing() + dev.spacing_error_m;
  if (!(x1_true - s_true > 0.0 && s_true > 0.0))
    throw InputError(fmt::format("the chain effects put the microphones at {} m and {} m from the sample; both must be "
                                 "in front of it, the near one closer",
                                 x1_true, x1_true - s_true));
  const Eigen::ArrayXcd h12 = transfer_function(reflection_from_admittance(y_measured), lossless_wavenumber(air, f_hz),
                                                x1, x1 - tube.spacing()) /
                              dev.mic_ratio;
  const Air tube_air = Air::at_celsius(air.temperature_c + dev.temperature_offset_k);
  const Eigen::ArrayXcd k_true =
      dev.tube_losses ? lossy_wavenumber(tube_air, f_hz, tube.diameter()) : lossless_wavenumber(tube_air, f_hz);
  return admittance_from_reflection(reflection_from_transfer(h12, k_true, x1_true, s_true)) *
         (air.rho_c() / tube_air.rho_c());
}

TwoMicrophoneChain::TwoMicrophoneChain(Eigen::ArrayXcd y_true, Eigen::ArrayXd f_hz, const Air& air,
                                       const TubeGeometry& tube)
    : y_true_(std::move(y_true)), f_(std::move(f_hz)), air_(air), tube_(tube) {
  const Eigen::ArrayXcd k = lossless_wavenumber(air_, f_);
  advance_ = (2.0 * kJ * tube_.mic1_distance() * k).exp();
  h_i_ = (-kJ * tube_.spacing() * k).exp();
  h_r_ = (kJ * tube_.spacing() * k).exp();
  // As true_transfer computes them for no deviation (x + 0.0 and the same air: the same values).
  const double x1 = tube_.mic1_distance() + 0.0, x2 = x1 - tube_.spacing() - 0.0;
  out1_ = (kJ * x1 * k).exp();
  back1_ = (-kJ * x1 * k).exp();
  out2_ = (kJ * x2 * k).exp();
  back2_ = (-kJ * x2 * k).exp();
  nominal_ = true_transfer(y_true_, ChainDeviation{});
}

Eigen::ArrayXcd TwoMicrophoneChain::true_transfer(const Eigen::ArrayXcd& y_true, const ChainDeviation& dev) const {
  const double x1 = tube_.mic1_distance() + dev.reference_plane_m;
  const double x2 = x1 - tube_.spacing() - dev.spacing_error_m;
  if (!(x2 > 0.0 && x2 < x1))
    throw InputError(fmt::format("the chain effects put the microphones at {} m and {} m from the sample; both must be "
                                 "in front of it, the near one closer",
                                 x1, x2));
  const Air tube_air = Air::at_celsius(air_.temperature_c + dev.temperature_offset_k);
  const Eigen::ArrayXcd y_tube = y_true * (tube_air.rho_c() / air_.rho_c());
  if (dev.temperature_offset_k == 0.0 && !dev.tube_losses && tube_air.c0 == air_.c0) {
    // transfer_function element by element as it evaluates it, with the nominal waves at a microphone
    // the deviation leaves in place.
    // A moved microphone: k is real, so e^{−jxk} = conj e^{jxk}, one sincos per point (equal to exp()'s
    // values to rounding).
    const Eigen::ArrayXcd r = reflection_from_admittance(y_tube), k = lossless_wavenumber(air_, f_);
    const auto pressure = [&](double x, bool nominal, const Eigen::ArrayXcd& out,
                              const Eigen::ArrayXcd& back) -> Eigen::ArrayXcd {
      if (nominal) return out + r * back;
      Eigen::ArrayXcd p(k.size());
      for (Eigen::Index i = 0; i < k.size(); ++i) {
        const cd wave = std::polar(1.0, x * k[i].real());
        p[i] = wave + r[i] * std::conj(wave);
      }
      return p;
    };
    const bool first = dev.reference_plane_m == 0.0, second = first && dev.spacing_error_m == 0.0;
    return pressure(x2, second, out2_, back2_) / pressure(x1, first, out1_, back1_);
  }
  const Eigen::ArrayXcd k_true =
      dev.tube_losses ? lossy_wavenumber(tube_air, f_, tube_.diameter()) : lossless_wavenumber(tube_air, f_);
  return transfer_function(reflection_from_admittance(y_tube), k_true, x1, x2);
}

Eigen::ArrayXcd TwoMicrophoneChain::processed(const Eigen::ArrayXcd& h12) const {
  // ISO 10534-2 eq. 17 (reflection_from_transfer) with the precomputed processing terms, element by
  // element as Eigen evaluates that expression (its exp() keeps it scalar), so the results are the same.
  Eigen::ArrayXcd r(h12.size());
  for (Eigen::Index i = 0; i < r.size(); ++i) r[i] = advance_[i] * (h12[i] - h_i_[i]) / (h_r_[i] - h12[i]);
  return admittance_from_reflection(r);
}

Eigen::ArrayXcd TwoMicrophoneChain::measure(const ChainDeviation& dev) const {
  const bool only_mic_ratio = dev.reference_plane_m == 0.0 && dev.spacing_error_m == 0.0 &&
                              dev.temperature_offset_k == 0.0 && !dev.tube_losses;
  return processed(dev.mic_ratio * (only_mic_ratio ? nominal_ : true_transfer(y_true_, dev)));
}

Eigen::ArrayXcd TwoMicrophoneChain::measure(const Eigen::ArrayXcd& y_true, const ChainDeviation& dev) const {
  ADMITGEN_ENSURE(y_true.size() == f_.size(), "{} admittances for {} frequencies", y_true.size(), f_.size());
  return processed(dev.mic_ratio * true_transfer(y_true, dev));
}

FrequencyRange working_range(const Air& air, const TubeGeometry& tube) {
  return {0.05 * air.c0 / tube.spacing(), std::min(0.45 * air.c0 / tube.spacing(), 0.586 * air.c0 / tube.diameter())};
}

}  // namespace admitgen

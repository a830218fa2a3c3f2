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
  const double x1 = tube.mic1_distance() + dev.reference_plane_m;
  const double x2 = x1 - tube.spacing() - dev.spacing_error_m;
  if (!(x2 > 0.0 && x2 < x1))
    throw InputError(fmt::format("the chain effects put the microphones at {} m and {} m from the sample; both must be "
                                 "in front of it, the near one closer",
                                 x1, x2));
  const Air tube_air = Air::at_celsius(air.temperature_c + dev.temperature_offset_k);
  const Eigen::ArrayXcd y_tube = y_true * (tube_air.rho_c() / air.rho_c());
  const Eigen::ArrayXcd k_true =
      dev.tube_losses ? lossy_wavenumber(tube_air, f_hz, tube.diameter()) : lossless_wavenumber(tube_air, f_hz);
  const Eigen::ArrayXcd h12 = dev.mic_ratio * transfer_function(reflection_from_admittance(y_tube), k_true, x1, x2);
  const Eigen::ArrayXcd r =
      reflection_from_transfer(h12, lossless_wavenumber(air, f_hz), tube.mic1_distance(), tube.spacing());
  return admittance_from_reflection(r);
}

FrequencyRange working_range(const Air& air, const TubeGeometry& tube) {
  return {0.05 * air.c0 / tube.spacing(), std::min(0.45 * air.c0 / tube.spacing(), 0.586 * air.c0 / tube.diameter())};
}

}  // namespace admitgen

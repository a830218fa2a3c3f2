// SPDX-License-Identifier: MIT
/// @file
/// The ISO 10534-2 two-microphone transfer-function method, both ways, in the e^{+jωt} convention of
/// docs/cli.md ("Effects"). x is the distance from the sample face; mic 1 (far) at x1, mic 2 (near) at x2 = x1 − s:
///
///   p(x) = e^{jkx} + R e^{−jkx},   H12 = p(x2)/p(x1)                      (forward: what the mics see)
///   R = e^{2jkx1} (H12 − e^{−jks})/(e^{jks} − H12)                         (processing: ISO eq. 17)
///
/// The processing inverts the forward model exactly when both use the same k, x1 and s; a measurement
/// effect is a true chain (k, positions, mic gains) that differs from the one processing assumes
/// (docs/cli.md "Effects"). The inversion is singular where sin ks = 0 (H_I = H_R), i.e. at
/// f = n c/(2s); ISO's working range keeps 0.05 c/s < f < min(0.45 c/s, 0.586 c/d).
#pragma once

#include "physics/air.hpp"

#include <Eigen/Core>

#include <complex>

namespace admitgen {

/// Impedance-tube geometry [m]. Invariant: all positive, s < x1 (both mics in front of the sample).
class TubeGeometry {
 public:
  /// Throws InputError naming the option (--tube-diameter, --mic-spacing, --mic-distance) at fault.
  TubeGeometry(double diameter_m, double spacing_m, double mic1_distance_m);
  double diameter() const { return d_; }
  double spacing() const { return s_; }
  double mic1_distance() const { return x1_; }
  double mic2_distance() const { return x1_ - s_; }

 private:
  double d_, s_, x1_;
};

/// R = (1 − y)/(1 + y) and back, y = (1 − R)/(1 + R).
Eigen::ArrayXcd reflection_from_admittance(const Eigen::ArrayXcd& y);
Eigen::ArrayXcd admittance_from_reflection(const Eigen::ArrayXcd& r);

/// H12 = p(x2)/p(x1) for reflection R and wavenumbers k (complex if the tube is lossy).
Eigen::ArrayXcd transfer_function(const Eigen::ArrayXcd& r, const Eigen::ArrayXcd& k, double x1, double x2);

/// ISO 10534-2: R from H12 with the processing's k, x1 and s.
Eigen::ArrayXcd reflection_from_transfer(const Eigen::ArrayXcd& h12, const Eigen::ArrayXcd& k, double x1, double s);

/// Lossless wavenumber ω/c0 at f_hz, as processing assumes it.
Eigen::ArrayXcd lossless_wavenumber(const Air& air, const Eigen::ArrayXd& f_hz);

/// Wavenumber with the tube-wall attenuation of ISO 10534-2 as docs/cli.md writes it:
///   k = ω/c0 + (1 − j)·0.0194·√f/(c0·d).
Eigen::ArrayXcd lossy_wavenumber(const Air& air, const Eigen::ArrayXd& f_hz, double diameter_m);

/// How the true chain differs from the one processing assumes (each zero / false / 1 = no effect).
struct ChainDeviation {
  double reference_plane_m = 0.0;     ///< sample face δ further than assumed: both mics δ further away
  double spacing_error_m = 0.0;       ///< near mic at x1 − s − δ (far mic stays at x1)
  double temperature_offset_k = 0.0;  ///< the tube's air is at T + ΔT
  bool tube_losses = false;           ///< true k lossy, processed lossless
  std::complex<double> mic_ratio{1.0, 0.0};  ///< H12' = H12·(1 + gain)·e^{jφ}
};

/// y as the ISO processing (at temperature `air`, lossless, nominal geometry) reports it for a sample
/// of true admittance y_true (normalised by `air`'s ρ0c0) measured through the deviating chain:
///   y_tube = y_true·ρ0c0(T+ΔT)/ρ0c0(T), R_t = (1 − y_tube)/(1 + y_tube),
///   H12 = mic_ratio·p_t(x1 + δ_ref − s − δ_s)/p_t(x1 + δ_ref) with k_t of air at T + ΔT (lossy if asked),
///   R = ISO(H12; ω/c(T), x1, s), y = (1 − R)/(1 + R).
/// Throws InputError if a deviation moves a microphone onto or behind the sample face.
Eigen::ArrayXcd measure_through_chain(const Eigen::ArrayXcd& y_true, const Eigen::ArrayXd& f_hz, const Air& air,
                                      const TubeGeometry& tube, const ChainDeviation& deviation);

/// The inverse of measure_through_chain: the true admittance of a sample whose processed admittance is
/// y_measured, had the chain deviated by `deviation` (docs/diagnosis.md, "Physics as the reference"). H12 is
/// recovered from y_measured with the processing's k, x1 and s, divided by the mic ratio, and processed again
/// with the true chain's k (temperature, losses), x1 + δ_ref and s + δ_s; y_tube is then normalised back by
/// ρ0c0(T+ΔT)/ρ0c0(T). Throws InputError as measure_through_chain.
Eigen::ArrayXcd correct_through_chain(const Eigen::ArrayXcd& y_measured, const Eigen::ArrayXd& f_hz, const Air& air,
                                      const TubeGeometry& tube, const ChainDeviation& deviation);

/// measure_through_chain for one sample, frequency grid, air and tube, with what does not depend on the
/// deviation computed once (for `diagnose`, which evaluates thousands of deviations): the processing's
/// e^{2jkx1}, H_I and H_R, and the nominal chain's H12, so a pure microphone mismatch costs one product
/// and the ISO inversion. Results equal measure_through_chain's to the last bit.
class TwoMicrophoneChain {
 public:
  TwoMicrophoneChain(Eigen::ArrayXcd y_true, Eigen::ArrayXd f_hz, const Air& air, const TubeGeometry& tube);
  /// y as processed for this sample through the deviating chain (throws as measure_through_chain).
  Eigen::ArrayXcd measure(const ChainDeviation& deviation) const;
  /// Another sample's y_true through the same chain: measure_through_chain(y_true, f_hz, air, tube,
  /// deviation) with the processing terms of this chain, and the microphones' travelling waves of the
  /// nominal chain when the deviation leaves positions, temperature and losses alone (same values).
  Eigen::ArrayXcd measure(const Eigen::ArrayXcd& y_true, const ChainDeviation& deviation) const;

 private:
  /// H12 the microphones see through the deviating chain, before the mic ratio.
  Eigen::ArrayXcd true_transfer(const Eigen::ArrayXcd& y_true, const ChainDeviation& deviation) const;
  /// The ISO 10534-2 processing of h12 into y.
  Eigen::ArrayXcd processed(const Eigen::ArrayXcd& h12) const;

  Eigen::ArrayXcd y_true_;
  Eigen::ArrayXd f_;
  Air air_;
  TubeGeometry tube_;
  Eigen::ArrayXcd advance_, h_i_, h_r_;  ///< processing: e^{2jkx1}, e^{−jks}, e^{jks} with k = ω/c0
  /// e^{±jkx} at the nominal microphone positions x1 and x2 = x1 − s (transfer_function's waves)
  Eigen::ArrayXcd out1_, back1_, out2_, back2_;
  Eigen::ArrayXcd nominal_;              ///< true_transfer of the nominal chain
};

/// ISO 10534-2 working range [f_lo, f_hi] in Hz: 0.05 c/s and min(0.45 c/s, 0.586 c/d).
struct FrequencyRange {
  double lo_hz;
  double hi_hz;
};
FrequencyRange working_range(const Air& air, const TubeGeometry& tube);

}  // namespace admitgen

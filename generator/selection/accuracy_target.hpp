// SPDX-License-Identifier: MIT
/// @file
/// The accuracy a fit must reach (docs/method.md, "Accuracy target"), measured on what ships: the passive
/// estimate of an order (passivity/passive_estimate.hpp). The unit is absorption per one-third-octave band, as
/// users and engines read it:
///
///   Δα_b = max_{i∈b} | α(G_i) − α(D_i) |,   α = 1 − |(1 − y)/(1 + y)|²,
///
/// over the data points i in band b (IEC 61260-1 base-10 bands, f_m = 1000·10^{x/10} Hz, edges f_m·10^{±1/20};
/// every band whose mid-band frequency lies within the data). An order meets the target when Δα_b ≤
/// max_band_delta_alpha in every band and, if set, its relative RMS residual ‖D − G‖/‖D‖ ≤ max_relative_rms.
/// The maximum over the band's points, not the band mean: a mean lets a model pass that misses a narrow feature
/// by averaging its overshoot and undershoot (on round_10cm a Q1S2 with a 5 % residual met a mean target of 0.01),
/// and the phase of the reflection it also misses matters to an auralization. The price is that measurement noise
/// counts: noisy data (σ ≈ 0.01 per component) cannot meet 0.01, and the fit says so in a warning.
#pragma once

#include "data/measurement.hpp"
#include "model/order.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace admitgen {

/// 0.01 by default: below the spread of α between laboratories measuring one sample by ISO 10534-2, and below the
/// absorption change a just-noticeable change of reverberation time needs unless the surface dominates a live room
/// (docs/method.md, "Accuracy target").
inline constexpr double kDefaultTargetAlpha = 0.01;

struct AccuracyTarget {
  double max_band_delta_alpha = kDefaultTargetAlpha;
  double max_relative_rms = 0.0;  ///< 0: not part of the target
  /// e.g. "|Δα| ≤ 0.01 in every band" or "|Δα| ≤ 0.01 in every band and relative RMS ≤ 0.02".
  std::string describe() const;
};

/// The accuracy of one model curve against the data.
struct OrderAccuracy {
  double relative_rms = 0.0;          ///< ‖D − G‖ / ‖D‖
  double max_band_delta_alpha = 0.0;  ///< max_b Δα_b (the largest |Δα| at any point of a covered band)
  double worst_band_hz = 0.0;         ///< mid-band frequency of that band
  /// Inside the worst band: the frequency where |D − G| peaks, and the width of that peak (where |D − G| stays
  /// above half its peak, in Hz): what the model misses there, e.g. a narrow spike of the data.
  double peak_hz = 0.0, peak_width_hz = 0.0;
  int peak_points = 0;  ///< data points of that peak
  /// max_b Δα_b over the covered points outside that peak: what the model misses beside it (equal to
  /// max_band_delta_alpha when the largest |Δα| lies elsewhere).
  double max_band_delta_alpha_beside_peak = 0.0;
  /// Lag-1 autocorrelation of the residual r = D − G over frequency, Re Σ r_i r̄_{i+1} / Σ |r_i|²: near 0 for
  /// measurement noise, near 1 for structure the model misses (0.97-0.99 on the bundled files' selected orders).
  double residual_lag1 = 0.0;
  bool meets = false;
};

/// The accuracy of (order, theta) against `data` under `target`.
OrderAccuracy order_accuracy(const Measurement& data, const Order& order, const Eigen::VectorXd& theta,
                             const AccuracyTarget& target);
/// The same for any admittance curve `g` at the data's frequencies (e.g. the passive bound's fit).
OrderAccuracy curve_accuracy(const Measurement& data, const Eigen::ArrayXcd& g, const AccuracyTarget& target);

/// The largest change of absorption between two model curves over the data's covered bands:
/// max_i | α(G_a,i) − α(G_b,i) | (what the larger order would change, in the note of a met target).
double band_alpha_change(const Measurement& data, const Order& order_a, const Eigen::VectorXd& theta_a,
                         const Order& order_b, const Eigen::VectorXd& theta_b);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "selection/accuracy_target.hpp"

#include "core/errors.hpp"
#include "model/multipole.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen {
namespace {

/// Index x of the one-third-octave band holding f (f_m = 1000·10^{x/10}, edges f_m·10^{±1/20}).
int band_index(double f_hz) { return static_cast<int>(std::floor(10.0 * std::log10(f_hz / 1000.0) + 0.5)); }
double band_center(int x) { return 1000.0 * std::pow(10.0, x / 10.0); }

/// Band index per point, −1 for points in a band whose mid-band frequency lies outside the data.
std::vector<int> point_bands(const Eigen::ArrayXd& f_hz) {
  std::vector<int> bands(static_cast<std::size_t>(f_hz.size()), -1);
  if (f_hz.size() == 0) return bands;
  const double lo = f_hz(0), hi = f_hz(f_hz.size() - 1);
  for (Eigen::Index i = 0; i < f_hz.size(); ++i) {
    const int x = band_index(f_hz(i));
    if (band_center(x) >= lo && band_center(x) <= hi) bands[static_cast<std::size_t>(i)] = x;
  }
  return bands;
}

/// max over the points of covered bands of |a_i − b_i|, and the index of that point (−1 when no band is covered);
/// the points skip_lo … skip_hi left out.
double max_in_bands(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXd& a, const Eigen::ArrayXd& b, Eigen::Index* at,
                    Eigen::Index skip_lo = 0, Eigen::Index skip_hi = -1) {
  const std::vector<int> bands = point_bands(f_hz);
  double worst = 0.0;
  Eigen::Index where = -1;
  for (Eigen::Index i = 0; i < f_hz.size(); ++i) {
    const double d = std::abs(a(i) - b(i));
    if (i >= skip_lo && i <= skip_hi) continue;
    if (bands[static_cast<std::size_t>(i)] >= 0 && (where < 0 || d > worst)) {
      worst = d;
      where = i;
    }
  }
  if (at) *at = where;
  return worst;
}

}  // namespace

std::string AccuracyTarget::describe() const {
  std::string text = fmt::format("|Δα| ≤ {} in every band", max_band_delta_alpha);
  if (max_relative_rms > 0.0) text += fmt::format(" and relative RMS ≤ {}", max_relative_rms);
  return text;
}


OrderAccuracy order_accuracy(const Measurement& data, const Order& order, const Eigen::VectorXd& theta,
                             const AccuracyTarget& target) {
  ADMITGEN_ENSURE(theta.size() == order.dim(), "theta {} for {}", theta.size(), order.name());
  return curve_accuracy(data, evaluate_multipole(order, theta, data.omega()), target);
}

OrderAccuracy curve_accuracy(const Measurement& data, const Eigen::ArrayXcd& g, const AccuracyTarget& target) {
  ADMITGEN_ENSURE(g.size() == data.size(), "{} model values for {} data points", g.size(), data.size());
  OrderAccuracy out;
  out.relative_rms = std::sqrt((data.y - g).abs2().sum() / data.y.abs2().sum());
  const Eigen::ArrayXcd r = data.y - g;
  if (r.size() > 1 && r.abs2().sum() > 0.0)
    out.residual_lag1 =
        (r.head(r.size() - 1) * r.tail(r.size() - 1).conjugate()).real().sum() / r.abs2().sum();
  Eigen::Index at = -1;
  const Eigen::ArrayXd alpha_model = absorption(g), alpha_data = absorption(data.y);
  out.max_band_delta_alpha = max_in_bands(data.f_hz, alpha_model, alpha_data, &at);
  out.max_band_delta_alpha_beside_peak = out.max_band_delta_alpha;
  if (at >= 0) {
    out.worst_band_hz = band_center(band_index(data.f_hz(at)));
    // The residual's peak inside the worst band, and its width at half height.
    const Eigen::ArrayXd size = r.abs();
    const double f_lo = out.worst_band_hz * std::pow(10.0, -0.05), f_hi = out.worst_band_hz * std::pow(10.0, 0.05);
    Eigen::Index peak = -1;
    for (Eigen::Index i = 0; i < data.size(); ++i)
      if (data.f_hz(i) >= f_lo && data.f_hz(i) < f_hi && (peak < 0 || size(i) > size(peak))) peak = i;
    if (peak >= 0) {
      Eigen::Index lo = peak, hi = peak;
      while (lo > 0 && size(lo - 1) > 0.5 * size(peak)) --lo;
      while (hi + 1 < data.size() && size(hi + 1) > 0.5 * size(peak)) ++hi;
      out.peak_hz = data.f_hz(peak);
      out.peak_width_hz = data.f_hz(hi) - data.f_hz(lo);
      out.peak_points = static_cast<int>(hi - lo + 1);
      out.max_band_delta_alpha_beside_peak = max_in_bands(data.f_hz, alpha_model, alpha_data, nullptr, lo, hi);
    }
  }
  out.meets = out.max_band_delta_alpha <= target.max_band_delta_alpha &&
              (target.max_relative_rms <= 0.0 || out.relative_rms <= target.max_relative_rms);
  return out;
}

double band_alpha_change(const Measurement& data, const Order& order_a, const Eigen::VectorXd& theta_a,
                         const Order& order_b, const Eigen::VectorXd& theta_b) {
  const Eigen::ArrayXd w = data.omega();
  return max_in_bands(data.f_hz, absorption(evaluate_multipole(order_a, theta_a, w)),
                      absorption(evaluate_multipole(order_b, theta_b, w)), nullptr);
}

}  // namespace admitgen

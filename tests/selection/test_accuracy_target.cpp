// SPDX-License-Identifier: MIT
// The accuracy target (selection/accuracy_target.hpp): the largest |Δα| per one-third-octave band of a model curve
// against the data, checked against α = 4 Re y / |1 + y|² computed here by hand at a perturbed point.
#include "model/multipole.hpp"
#include "selection/accuracy_target.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

using namespace admitgen;

namespace {

/// α of a normalised admittance, 1 − |(1 − y)/(1 + y)|² = 4 Re y / |1 + y|² (independent of data/measurement.cpp).
double alpha_by_hand(std::complex<double> y) { return 4.0 * y.real() / std::norm(1.0 + y); }

/// Q0S1 data at 200 log-spaced points 300-3000 Hz, exactly the model: G_inf = 0.3, one pair.
struct Fixture {
  Order order{0, 1};
  Eigen::VectorXd theta = (Eigen::VectorXd(5) << 0.3, 0.2, 0.05, 2000.0, 6000.0).finished();
  Measurement data;
  Fixture() {
    data.f_hz = Eigen::ArrayXd::LinSpaced(200, std::log10(300.0), std::log10(3000.0)).unaryExpr(
        [](double e) { return std::pow(10.0, e); });
    data.y = evaluate_multipole(order, theta, data.omega());
  }
};

}  // namespace

TEST_CASE("accuracy target: the model itself meets any target, one perturbed point sets the band and the figure") {
  Fixture fx;
  const AccuracyTarget target{0.01, 0.0};
  const OrderAccuracy exact = order_accuracy(fx.data, fx.order, fx.theta, target);
  CHECK(exact.relative_rms < 1e-14);
  CHECK(exact.max_band_delta_alpha < 1e-14);
  CHECK(exact.meets);

  // Perturb the point nearest 1000 Hz (band x = 0: 891-1122 Hz, mid-band 1000 Hz) by 0.02 in Re y.
  Eigen::Index k = 0;
  (fx.data.f_hz - 1000.0).abs().minCoeff(&k);
  const std::complex<double> model_y = fx.data.y(k);
  fx.data.y(k) += 0.02;
  const double expected = std::abs(alpha_by_hand(fx.data.y(k)) - alpha_by_hand(model_y));
  const OrderAccuracy a = order_accuracy(fx.data, fx.order, fx.theta, target);
  CHECK(a.max_band_delta_alpha == doctest::Approx(expected).epsilon(1e-12));  // rounding of a few operations
  CHECK(a.worst_band_hz == doctest::Approx(1000.0).epsilon(1e-12));
  CHECK(a.peak_hz == fx.data.f_hz(k));
  CHECK(a.meets == (expected <= 0.01));
  // ‖D − G‖/‖D‖ with one residual of 0.02.
  CHECK(a.relative_rms == doctest::Approx(0.02 / std::sqrt(fx.data.y.abs2().sum())).epsilon(1e-12));
  // A target below the perturbation's Δα is missed; a relative-RMS target below its residual is missed too.
  CHECK_FALSE(order_accuracy(fx.data, fx.order, fx.theta, AccuracyTarget{0.5 * expected, 0.0}).meets);
  CHECK(order_accuracy(fx.data, fx.order, fx.theta, AccuracyTarget{2.0 * expected, 0.0}).meets);
  CHECK_FALSE(order_accuracy(fx.data, fx.order, fx.theta, AccuracyTarget{2.0 * expected, 0.5 * a.relative_rms}).meets);
}

TEST_CASE("accuracy target: points of a band whose mid-band frequency lies outside the data do not count") {
  Fixture fx;
  // The last point, 3000 Hz, lies in band x = round(10 log10 3) = 5, whose mid-band frequency 3162 Hz lies above
  // the data: its |Δα| is left out, however large.
  fx.data.y(fx.data.size() - 1) += 0.05;
  CHECK(order_accuracy(fx.data, fx.order, fx.theta, AccuracyTarget{}).max_band_delta_alpha < 1e-14);
  CHECK(band_alpha_change(fx.data, fx.order, fx.theta, fx.order, fx.theta) == 0.0);
}

// SPDX-License-Identifier: MIT
// Effects of docs/cli.md: parsing by documented name and parameters, and the sample effects' closed forms
// (frame_resonance, fractional_order, edge_gap, air_gap) against exact values and docs/physics.md §5.1 sizes.
#include "core/errors.hpp"
#include "physics/effects.hpp"
#include "physics/synthetic_measurement.hpp"
#include "physics/transfer_matrix.hpp"
#include "physics_test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

namespace admitgen {
namespace {

using cd = std::complex<double>;

TEST_CASE("effects parse by their contract names and print back canonically") {
  const char* canonical[] = {"none",
                             "reference_plane:delta_m=0.001",
                             "mic_spacing:delta_m=-0.0005",
                             "mic_mismatch:gain=0.01,phase_deg=0.5",
                             "temperature:delta_k=2",
                             "tube_losses",
                             "edge_gap:width_m=0.0005,depth_m=0.05",
                             "frame_resonance:f0_hz=600,q=8,y_peak=0.3",
                             "fractional_order:c_plus=0.01,c_minus=0.02,f_ref_hz=1000",
                             "air_gap:gap_m=0.005",
                             "heteroscedastic_noise:scale=0.1"};
  for (const char* text : canonical) {
    CAPTURE(text);
    CHECK(to_string(parse_effect(text)) == text);
  }
  CHECK(to_string(parse_effect("edge_gap: depth_m = 5cm, width_m = 0.5mm")) == "edge_gap:width_m=0.0005,depth_m=0.05");
  CHECK(std::get<MicMismatch>(parse_effect("mic_mismatch:gain=0,phase_deg=1")).phase_deg == 1.0);
}

TEST_CASE("malformed effects are input errors that say what is wrong") {
  test::check_input_errors([](const std::string& text) { return parse_effect(text); }, {
      {"frame_ressonance:f0_hz=600,q=8,y_peak=0.3", "unknown effect 'frame_ressonance'"},
      {"frame_resonance:f0_hz=600,q=8", "missing parameter 'y_peak'"},
      {"frame_resonance:f0_hz=600,q=8,y_peak=0.3,width=1", "unknown parameter 'width'"},
      {"frame_resonance:f0_hz=-600,q=8,y_peak=0.3", "'f0_hz' must be positive"},
      {"reference_plane:delta_m=abc", "not a finite number"},
      {"reference_plane:delta_m=1%", "unit '%' does not fit"},
      {"reference_plane:delta_m=1mm,delta_m=2mm", "given twice"},
      {"mic_mismatch:gain=-1,phase_deg=0", "'gain' must exceed -1"},
      {"tube_losses:d=1", "unknown parameter 'd'"},
  });
}

TEST_CASE("frame_resonance and fractional_order: exact values at f0 and f_ref") {
  const Eigen::ArrayXd f = (Eigen::ArrayXd(3) << 300.0, 600.0, 1200.0).finished();
  const Eigen::ArrayXcd y = Eigen::ArrayXcd::Constant(3, cd(0.2, -0.4));
  // y' − y = y_peak/(1 + jq(f/f0 − f0/f)): y_peak at f0; at f = 2f0 (and f0/2) the detuning is ±1.5q.
  const Eigen::ArrayXcd fr = apply_frame_resonance(FrameResonance{600.0, 8.0, 0.3}, f, y);
  CHECK(std::abs(fr[1] - y[1] - 0.3) <= 1e-15);
  CHECK(std::abs(fr[2] - y[2] - 0.3 / cd(1.0, 12.0)) <= 1e-15);
  CHECK(std::abs(fr[0] - y[0] - 0.3 / cd(1.0, -12.0)) <= 1e-15);
  // (jω/ω_r)^{±1/2} at f = f_ref is e^{±jπ/4}; at f = 4 f_ref it is 2e^{jπ/4} and ½e^{−jπ/4}.
  const Eigen::ArrayXcd fo = apply_fractional_order(FractionalOrder{0.01, 0.02, 300.0}, f, y);
  const cd e45 = std::polar(1.0, static_cast<double>(EIGEN_PI) / 4.0);
  CHECK(std::abs(fo[0] - y[0] - (0.01 * e45 + 0.02 * std::conj(e45))) <= 1e-15);
  CHECK(std::abs(fo[2] - y[2] - (0.02 * e45 + 0.01 * std::conj(e45))) <= 1e-15);
}

TEST_CASE("edge_gap: slit admittance limits and epsilon") {
  const Air air = Air::at_celsius(20.0);
  SUBCASE("a narrow slit at low frequency is an isothermal compliance: y_slit -> j w h rho0 c0/P0") {
    // At 5 Hz, w = 0.1 mm: σ_t² ≈ 0.004j, so K_e = P0 (1 + 0.4 σ_t²/(3γ) + …), 4e-4 from P0; the viscous
    // density ρ_e ≈ 12η/(jωw²) gives |k h| ≈ 0.013 for h = 5 mm and tan(kh)/(kh) − 1 ≈ (kh)²/3 ≈ 6e-5.
    // Tolerance 1e-3 relative: twice the sum of both.
    const double w = 1e-4, h = 0.005, f = 5.0;
    const cd y = slit_admittance(w, h, air, test::at(f))[0];
    const cd compliance(0.0, 2.0 * EIGEN_PI * f * h * air.rho_c() / air.p0);
    CHECK(std::abs(y - compliance) / std::abs(compliance) <= 2e-3);
  }
  SUBCASE("a wide slit is a lossless rigid-backed air column: y_slit -> j tan(k h)") {
    // w = 20 mm at 500 Hz: viscous/thermal boundary layers (≈ 0.1 mm) are 1 % of w/2, so the relative
    // departure from lossless air is about 2δ/w ≈ 1-2 %: tolerance 3 %.
    const double w = 0.02, h = 0.05, f = 500.0;
    const cd y = slit_admittance(w, h, air, test::at(f))[0];
    const cd lossless(0.0, std::tan(2.0 * EIGEN_PI * f * h / air.c0));
    CHECK(std::abs(y - lossless) / std::abs(lossless) <= 0.03);
    CHECK(y.real() > 0.0);
  }
  SUBCASE("epsilon = 1 - (1 - 2w/d)^2 weights the slit: y' = (1-eps) y + eps y_slit") {
    const Eigen::ArrayXd f = test::at(800.0);
    const Eigen::ArrayXcd y = Eigen::ArrayXcd::Constant(1, cd(0.5, 0.1));
    const Eigen::ArrayXcd ym = apply_edge_gap(EdgeGap{1e-3, 0.05}, 0.1, air, f, y);
    const double eps = 1.0 - 0.98 * 0.98;
    CHECK(std::abs(ym[0] - ((1.0 - eps) * y[0] + eps * slit_admittance(1e-3, 0.05, air, f)[0])) <= 1e-15);
    CHECK_THROWS_AS(apply_edge_gap(EdgeGap{0.06, 0.05}, 0.1, air, f, y), InputError);
  }
}

TEST_CASE("edge_gap: the slit admittance equals the textbook formula with complex tanh, sqrt and tan") {
  // Reference: docs/physics.md §5.1 f written with std::tanh/std::tan on std::complex (glibc's ctanh/ctan),
  // against SlitModel's real-exponential form. Grid: the edge_gap prior of `diagnose` and beyond, w 0.02-5 mm,
  // h 2-300 mm, f 10 Hz-12 kHz. Tolerance: both forms are accurate to a few ulp before two ill-conditioned
  // steps, 1 − tanh(σ)/σ (condition ≈ 1/|1 − tanh(σ)/σ| ≤ 3/(2x²) ≈ 6e3 at the smallest x = 0.014 here) and
  // tan(kh) near the quarter-wave pole (condition ≈ 1/|1 + e^{−2jkh}|, ≤ 1e3 for the slit's losses at
  // w ≤ 5 mm). 1e-9 relative is about 10 ulp times both condition numbers.
  const Air air = Air::at_celsius(20.0);
  const Eigen::ArrayXd f = Eigen::ArrayXd::LinSpaced(400, std::log(10.0), std::log(12000.0)).exp();
  double worst = 0.0;
  for (double w : {2e-5, 5e-5, 1e-4, 3e-4, 1e-3, 3e-3, 5e-3})
    for (double h : {0.002, 0.02, 0.05, 0.12, 0.3}) {
      const Eigen::ArrayXcd y = slit_admittance(w, h, air, f);
      for (Eigen::Index i = 0; i < f.size(); ++i) {
        const double omega = 2.0 * EIGEN_PI * f[i];
        const cd sv = (w / 2.0) * std::sqrt(cd(0.0, omega / air.nu()));
        const cd st = (w / 2.0) * std::sqrt(cd(0.0, omega * air.prandtl / air.nu()));
        const cd rho = air.rho0 / (1.0 - std::tanh(sv) / sv);
        const cd bulk = air.gamma * air.p0 / (1.0 + (air.gamma - 1.0) * std::tanh(st) / st);
        const cd reference = air.rho_c() * cd(0.0, 1.0) * std::tan(omega * std::sqrt(rho / bulk) * h) /
                             std::sqrt(rho * bulk);
        worst = std::max(worst, std::abs(y[i] - reference) / std::abs(reference));
      }
    }
  MESSAGE("largest relative difference " << worst);
  CHECK(worst <= 1e-9);
}

TEST_CASE("edge_gap: the tabulated slit fluid gives SlitModel's admittance to 1e-9 relative") {
  // TabulatedSlitModel interpolates U = (ρ0c0/Z_c)(1 + 1/x) and V = S x/(1 + x) in s = ln x (4096 nodes
  // over x 0.01-100, h = 2.25e-3) by 4-point Lagrange: error ≤ 0.023 h⁴ max|d⁴/ds⁴| ≈ 6e-13 for
  // derivatives of order 10 (the e^{−2x} cos 2x ripple of tanh peaks near x ≈ 3-5), then tan(ω S h)
  // amplifies the error of S by at most the quarter-wave condition ≈ 1e3 of the test above. Tolerance
  // 1e-9 relative, the same as the exact form's against the textbook one. Grid: as that test, which
  // covers the edge_gap prior of `diagnose` (w 0.05-3 mm, h 5-200 mm) and x from 0.01 to 200, so both
  // ends of the table and the exact fallback beyond them are crossed.
  const Air air = Air::at_celsius(20.0);
  const Eigen::ArrayXd f = Eigen::ArrayXd::LinSpaced(400, std::log(10.0), std::log(12000.0)).exp();
  const SlitModel exact(air, f);
  const TabulatedSlitModel table(air, f);
  double worst = 0.0;
  for (double w : {2e-5, 5e-5, 1e-4, 3e-4, 1e-3, 3e-3, 5e-3})
    for (double h : {0.002, 0.02, 0.05, 0.12, 0.3}) {
      const Eigen::ArrayXcd reference = exact.admittance(w, h), y = table.admittance(w, h);
      worst = std::max(worst, ((y - reference).abs() / reference.abs()).maxCoeff());
    }
  MESSAGE("largest relative difference " << worst);
  CHECK(worst <= 1e-9);
  const Eigen::ArrayXcd y = Eigen::ArrayXcd::Constant(f.size(), cd(0.5, 0.1));
  const EdgeGap e{1e-3, 0.05};
  CHECK(((table.edge_gap(e, 0.1, y) - exact.edge_gap(e, 0.1, y)).abs() <= 1e-9 * y.abs()).all());
  CHECK_THROWS_AS(table.edge_gap(EdgeGap{0.06, 0.05}, 0.1, y), InputError);
}

TEST_CASE("sample effect sizes of docs/physics.md 5.1 for the reference case (Miki 10 kPa s/m2, 50 mm, d = 100 mm)") {
  // docs/physics.md quotes these sizes (computed with admitgen's air); figures with 1-2 significant digits
  // are matched to ±20 % of the value.
  const Air air = Air::at_celsius(20.0);
  const Eigen::ArrayXd f = Eigen::ArrayXd::LinSpaced(1801, 100.0, 1900.0);
  const LayeredAbsorber miki{{PorousLayer{Miki{10000.0}, 0.05}}};
  const Eigen::ArrayXcd y = surface_admittance(miki, air, f);
  const auto max_delta_alpha = [&](const Eigen::ArrayXcd& ym) {
    double worst = 0.0;
    for (Eigen::Index i = 0; i < f.size(); ++i)
      worst = std::max(worst, std::abs(test::absorption_of(ym[i]) - test::absorption_of(y[i])));
    return worst;
  };
  const auto near = [](double value, double published) { return std::abs(value - published) <= 0.2 * published; };
  for (const auto& [w, published] : {std::pair{0.25e-3, 0.002}, std::pair{0.5e-3, 0.007}, std::pair{1e-3, 0.052}}) {
    const double got = max_delta_alpha(apply_edge_gap(EdgeGap{w, 0.05}, 0.1, air, f, y));
    MESSAGE("edge_gap w = ", w, " m: max |d alpha| = ", got, " (docs/physics.md ", published, ")");
    CHECK(near(got, published));
  }
  const double frame = max_delta_alpha(apply_frame_resonance(FrameResonance{600.0, 8.0, 0.3}, f, y));
  MESSAGE("frame_resonance 600 Hz, Q 8, y_peak 0.3: max |d alpha| = ", frame, " (docs/physics.md 0.23)");
  CHECK(near(frame, 0.23));
  for (const auto& [gap, published] : {std::pair{1e-3, 0.013}, std::pair{5e-3, 0.063}}) {
    LayeredAbsorber with_gap = miki;
    with_gap.layers.push_back(AirLayer{gap});
    const double got = max_delta_alpha(surface_admittance(with_gap, air, f));
    MESSAGE("air_gap ", gap, " m: max |d alpha| = ", got, " (docs/physics.md ", published, ")");
    CHECK(near(got, published));
  }
}

}  // namespace
}  // namespace admitgen

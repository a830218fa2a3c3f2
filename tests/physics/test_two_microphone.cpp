// SPDX-License-Identifier: MIT
// The ISO 10534-2 chain R → H12 → R, and each chain effect of docs/cli.md against its first-order
// closed form (docs/physics.md §5.1 a-d, m), derived here independently of the chain code:
//   ∂y/∂R = −2/(1 + R)²,  ∂R/∂H = (H_R − H_I) e^{2jkx1}/(H_R − H)²,  p(x) = e^{jkx} + R e^{−jkx},
//   a. reference plane  ∂y/∂δ = 4jkR/(1 + R)²                                   (R_m = R e^{−2jkδ})
//   b. mic spacing      ∂H/∂δ_s = −p'(x2)/p(x1),  p'(x) = jk(e^{jkx} − R e^{−jkx})
//   c. temperature      the chain at c' processed at c equals the chain at c with all distances × c/c',
//                       i.e. δ = x1 ε and δ_s = s ε with ε = c/c' − 1, plus y → y ρ0c0(T+ΔT)/ρ0c0(T)
//   d. tube losses      ∂H/∂k · (1 − j) α_K,  α_K = 0.0194 √f/(c d)
//   m. mic mismatch     ∂H = H (gain + jφ)
// Reference case (docs/physics.md §5.0): Miki σ = 10 kPa·s/m², 50 mm, rigid-backed; tube d = 100 mm,
// x1 = 100 mm, s = 50 mm; 100-1900 Hz; air at 20 °C as docs/cli.md defines it.
#include "physics/effects.hpp"
#include "physics/transfer_matrix.hpp"
#include "physics/two_microphone.hpp"
#include "physics_test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>

namespace admitgen {
namespace {

using cd = std::complex<double>;
constexpr cd kJ{0.0, 1.0};

struct ReferenceCase {
  Air air = Air::at_celsius(20.0);
  TubeGeometry tube{0.1, 0.05, 0.1};
  Eigen::ArrayXd f = Eigen::ArrayXd::LinSpaced(37, 100.0, 1900.0);
  Eigen::ArrayXcd y = surface_admittance(LayeredAbsorber{{PorousLayer{Miki{10000.0}, 0.05}}}, air, f);

  double k(Eigen::Index i) const { return 2.0 * EIGEN_PI * f[i] / air.c0; }
  cd r(Eigen::Index i) const { return (1.0 - y[i]) / (1.0 + y[i]); }
  cd p(Eigen::Index i, double x) const { return std::exp(kJ * k(i) * x) + r(i) * std::exp(-kJ * k(i) * x); }
  cd dp(Eigen::Index i, double x) const { return kJ * k(i) * (std::exp(kJ * k(i) * x) - r(i) * std::exp(-kJ * k(i) * x)); }
  cd h(Eigen::Index i) const { return p(i, tube.mic2_distance()) / p(i, tube.mic1_distance()); }
  /// ∂y/∂H through the processing: ∂y/∂R · ∂R/∂H.
  cd dy_dh(Eigen::Index i) const {
    const double ks = k(i) * tube.spacing();
    const cd h_i = std::exp(-kJ * ks), h_r = std::exp(kJ * ks);
    const cd dr_dh = (h_r - h_i) * std::exp(2.0 * kJ * k(i) * tube.mic1_distance()) / std::pow(h_r - h(i), 2);
    return -2.0 / std::pow(1.0 + r(i), 2) * dr_dh;
  }
  cd j_reference(Eigen::Index i) const { return 4.0 * kJ * k(i) * r(i) / std::pow(1.0 + r(i), 2); }
  cd j_spacing(Eigen::Index i) const { return dy_dh(i) * (-dp(i, tube.mic2_distance()) / p(i, tube.mic1_distance())); }

  Eigen::ArrayXcd measured(const ChainDeviation& d) const { return measure_through_chain(y, f, air, tube, d); }
};

/// max_i |y_m − y − J_i| / |J_i| over the band.
template <class Linear>
double worst_relative_error(const ReferenceCase& rc, const Eigen::ArrayXcd& measured, Linear linear) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < rc.f.size(); ++i) {
    const cd predicted = linear(i);
    worst = std::max(worst, std::abs(measured[i] - rc.y[i] - predicted) / std::abs(predicted));
  }
  return worst;
}

TEST_CASE("two-microphone chain: R -> H12 -> R is the identity without effects") {
  // Both directions evaluate exponentials of the same k, x; the inversion divides by H_R − H12, which
  // stays ≥ 0.08 in this band (asserted), so rounding stays ~1e-15 · 1/0.08: 1e-12 is a safe bound.
  const ReferenceCase rc;
  const Eigen::ArrayXcd r = reflection_from_admittance(rc.y);
  for (const bool lossy : {false, true}) {
    CAPTURE(lossy);
    const Eigen::ArrayXcd k = lossy ? lossy_wavenumber(rc.air, rc.f, 0.1) : lossless_wavenumber(rc.air, rc.f);
    const Eigen::ArrayXcd h = transfer_function(r, k, rc.tube.mic1_distance(), rc.tube.mic2_distance());
    CHECK((((kJ * rc.tube.spacing() * k).exp() - h).abs() > 0.08).all());
    const Eigen::ArrayXcd back = reflection_from_transfer(h, k, rc.tube.mic1_distance(), rc.tube.spacing());
    CHECK((back - r).abs().maxCoeff() <= 1e-12);
  }
  CHECK((reflection_from_admittance(rc.measured(ChainDeviation{})) - r).abs().maxCoeff() <= 1e-12);
}

TEST_CASE("two-microphone chain with precomputed terms equals the ISO pieces composed, to the last bit") {
  // What `diagnose` evaluates for every deviation (TwoMicrophoneChain::measure) against the public steps
  // written out: y_tube, k_true, H12 = ratio · transfer_function, ISO inversion, y. The same operations
  // on the same numbers, so equality is exact.
  const ReferenceCase rc;
  const TwoMicrophoneChain chain(rc.y, rc.f, rc.air, rc.tube);
  ChainDeviation ratio_only, spacing_only, plane_only, several;
  ratio_only.mic_ratio = std::polar(1.02, 0.01);
  spacing_only.spacing_error_m = 3e-4;
  plane_only.reference_plane_m = -2e-3;
  several.reference_plane_m = 1e-3;
  several.spacing_error_m = -2e-4;
  several.temperature_offset_k = 3.0;
  several.tube_losses = true;
  several.mic_ratio = std::polar(0.99, -0.02);
  for (const ChainDeviation& d : {ChainDeviation{}, ratio_only, spacing_only, plane_only, several}) {
    const double x1 = rc.tube.mic1_distance() + d.reference_plane_m;
    const double x2 = x1 - rc.tube.spacing() - d.spacing_error_m;
    const Air tube_air = Air::at_celsius(rc.air.temperature_c + d.temperature_offset_k);
    const Eigen::ArrayXcd y_tube = rc.y * (tube_air.rho_c() / rc.air.rho_c());
    const Eigen::ArrayXcd k_true = d.tube_losses ? lossy_wavenumber(tube_air, rc.f, rc.tube.diameter())
                                                 : lossless_wavenumber(tube_air, rc.f);
    const Eigen::ArrayXcd h12 = d.mic_ratio * transfer_function(reflection_from_admittance(y_tube), k_true, x1, x2);
    const Eigen::ArrayXcd expected = admittance_from_reflection(reflection_from_transfer(
        h12, lossless_wavenumber(rc.air, rc.f), rc.tube.mic1_distance(), rc.tube.spacing()));
    CHECK((chain.measure(d) == expected).all());
    CHECK((rc.measured(d) == expected).all());
    // Another sample through the same chain (a changed surface in a combined effect): the chain's
    // nominal waves reused when the deviation leaves positions, temperature and losses alone.
    const Eigen::ArrayXcd other = 0.9 * rc.y + 0.05;
    CHECK((chain.measure(other, d) == measure_through_chain(other, rc.f, rc.air, rc.tube, d)).all());
  }
}

TEST_CASE("reference_plane: the closed form R e^{-2jk delta} equals the chain with both mics delta further") {
  const ReferenceCase rc;
  const double delta = 2e-3;
  ChainDeviation d;
  d.reference_plane_m = delta;
  const Eigen::ArrayXcd closed = apply_reference_plane(ReferencePlane{delta}, rc.air, rc.f, rc.y);
  CHECK((closed - rc.measured(d)).abs().maxCoeff() <= 1e-12);
}

TEST_CASE("chain effects reproduce their first-order closed forms (docs/physics.md 5.1) for a small parameter") {
  // For a parameter of size ε the neglected terms are O(ε²): relative to the first-order term they are
  // a few times the dimensionless size of the perturbation (kδ, k δ_s, ΔT/T, α_K x1, gain), amplified at
  // most by 1/|1 + R| ≤ 1/0.5 here (asserted). Each bound below is 10 × that size; a wrong sign or factor
  // in a closed form gives a relative error ≥ 1 and fails.
  const ReferenceCase rc;
  const double k_max = 2.0 * EIGEN_PI * 1900.0 / rc.air.c0;
  for (Eigen::Index i = 0; i < rc.f.size(); ++i) REQUIRE(std::abs(1.0 + rc.r(i)) >= 0.5);

  SUBCASE("a. reference_plane") {
    const double delta = 1e-5;
    ChainDeviation d;
    d.reference_plane_m = delta;
    const double err = worst_relative_error(rc, rc.measured(d), [&](Eigen::Index i) { return delta * rc.j_reference(i); });
    CHECK(err <= 10.0 * k_max * delta);
  }
  SUBCASE("b. mic_spacing") {
    const double delta = 1e-5;
    ChainDeviation d;
    d.spacing_error_m = delta;
    const double err = worst_relative_error(rc, rc.measured(d), [&](Eigen::Index i) { return delta * rc.j_spacing(i); });
    CHECK(err <= 10.0 * k_max * delta / 0.08);  // H_R − H ≥ 0.08 enters the second derivative
  }
  SUBCASE("c. temperature") {
    const double dt = 0.01;
    ChainDeviation d;
    d.temperature_offset_k = dt;
    const Air hot = Air::at_celsius(20.0 + dt);
    const double eps = rc.air.c0 / hot.c0 - 1.0, kappa = hot.rho_c() / rc.air.rho_c() - 1.0;
    const double err = worst_relative_error(rc, rc.measured(d), [&](Eigen::Index i) {
      return rc.y[i] * kappa + rc.j_reference(i) * rc.tube.mic1_distance() * eps + rc.j_spacing(i) * rc.tube.spacing() * eps;
    });
    CHECK(err <= 10.0 * dt / 293.15 / 0.08);
  }
  SUBCASE("d. tube_losses") {
    ChainDeviation d;
    d.tube_losses = true;
    const Eigen::ArrayXcd measured = rc.measured(d);
    double alpha_x_max = 0.0;
    const double err = worst_relative_error(rc, measured, [&](Eigen::Index i) {
      const double x1 = rc.tube.mic1_distance(), x2 = rc.tube.mic2_distance();
      const cd p1 = rc.p(i, x1), p2 = rc.p(i, x2);
      const cd dh_dk = (x2 * rc.dp(i, x2) / rc.k(i) * p1 - x1 * rc.dp(i, x1) / rc.k(i) * p2) / (p1 * p1);
      const double attenuation = 0.0194 * std::sqrt(rc.f[i]) / (rc.air.c0 * rc.tube.diameter());
      alpha_x_max = std::max(alpha_x_max, attenuation * x1);
      return rc.dy_dh(i) * dh_dk * cd(1.0, -1.0) * attenuation;
    });
    CHECK(err <= 10.0 * alpha_x_max / 0.08);
  }
  SUBCASE("m. mic_mismatch, gain and phase") {
    const double gain = 1e-5, phase = 1e-5;  // phase in radians
    ChainDeviation d;
    d.mic_ratio = (1.0 + gain) * std::polar(1.0, phase);
    const double err = worst_relative_error(rc, rc.measured(d), [&](Eigen::Index i) {
      return rc.dy_dh(i) * rc.h(i) * (gain + kJ * phase);
    });
    CHECK(err <= 10.0 * (gain + phase) / 0.08);
  }
}

TEST_CASE("chain effect sizes of docs/physics.md 5.1 for the reference case") {
  // docs/physics.md quotes these sizes for this case (computed with admitgen's air);
  // figures printed to 1-2 significant digits are matched to ±15 % of the value.
  const ReferenceCase rc;
  const auto rel = [](cd a, cd b) { return std::abs(a - b) / std::abs(b); };
  const auto near = [](double value, double published) { return std::abs(value - published) <= 0.15 * published; };
  SUBCASE("reference_plane 1 mm: |dY|/|Y| 2.0 % at 500 Hz, 0.9 % at 1.5 kHz, alpha unchanged") {
    const Eigen::ArrayXd f = (Eigen::ArrayXd(2) << 500.0, 1500.0).finished();
    const Eigen::ArrayXcd y = surface_admittance(LayeredAbsorber{{PorousLayer{Miki{10000.0}, 0.05}}}, rc.air, f);
    const Eigen::ArrayXcd ym = apply_reference_plane(ReferencePlane{1e-3}, rc.air, f, y);
    CHECK(near(rel(ym[0], y[0]), 0.020));
    CHECK(near(rel(ym[1], y[1]), 0.009));
    CHECK(std::abs(test::absorption_of(ym[0]) - test::absorption_of(y[0])) <= 1e-12);
  }
  SUBCASE("temperature +1 K: max |d alpha| <= 0.0007, |dY|/|Y| about 0.35 %") {
    ChainDeviation d;
    d.temperature_offset_k = 1.0;
    const Eigen::ArrayXcd ym = rc.measured(d);
    double worst_alpha = 0.0, mean_rel = 0.0;
    for (Eigen::Index i = 0; i < rc.f.size(); ++i) {
      worst_alpha = std::max(worst_alpha, std::abs(test::absorption_of(ym[i]) - test::absorption_of(rc.y[i])));
      mean_rel += rel(ym[i], rc.y[i]) / static_cast<double>(rc.f.size());
    }
    MESSAGE("temperature +1 K: max |d alpha| = ", worst_alpha, ", mean |dY|/|Y| = ", mean_rel);
    CHECK(worst_alpha <= 0.0007 * 1.15);
    CHECK(near(mean_rel, 0.0035));
  }
  SUBCASE("mic_spacing 0.5 mm: max |d alpha| 0.004") {
    ChainDeviation d;
    d.spacing_error_m = 0.5e-3;
    const Eigen::ArrayXcd ym = rc.measured(d);
    double worst_alpha = 0.0;
    for (Eigen::Index i = 0; i < rc.f.size(); ++i)
      worst_alpha = std::max(worst_alpha, std::abs(test::absorption_of(ym[i]) - test::absorption_of(rc.y[i])));
    MESSAGE("mic_spacing 0.5 mm: max |d alpha| = ", worst_alpha);
    CHECK(near(worst_alpha, 0.004));
  }
  SUBCASE("tube_losses: rigid termination processed lossless reads alpha up to 0.007 (d = 100 mm)") {
    // A design note gave 0.005-0.007 without naming the band or the constant (0.0204 vs ISO's 0.0194);
    // the top of the range is matched here; the bottom is not (0.0034 at 100 Hz, growing like √f).
    const Eigen::ArrayXcd rigid = Eigen::ArrayXcd::Zero(rc.f.size());
    ChainDeviation d;
    d.tube_losses = true;
    const Eigen::ArrayXcd ym = measure_through_chain(rigid, rc.f, rc.air, rc.tube, d);
    double lo = 1.0, hi = 0.0;
    for (Eigen::Index i = 0; i < rc.f.size(); ++i) {
      lo = std::min(lo, test::absorption_of(ym[i]));
      hi = std::max(hi, test::absorption_of(ym[i]));
    }
    MESSAGE("tube_losses on a rigid termination: alpha ", lo, " - ", hi);
    CHECK(lo > 0.0);
    CHECK(near(hi, 0.007));
  }
}

}  // namespace
}  // namespace admitgen

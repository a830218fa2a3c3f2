// SPDX-License-Identifier: MIT
// What emit ships, measured as a user would: each bundled Basotect file's committed fit is emitted in every format
// at 48 kHz, one node of the runtime's own kernels (codegen/runtime_filter.hpp) is driven with steady tones, and the
// measured complex gain is compared with the continuous model the header names. Independent of the fidelity
// check's arithmetic (codegen/fidelity.hpp evaluates the dequantised coefficients in exact arithmetic; here the
// kernels run, in their own formats, with quantised input). The fits are committed (samples/fits/basotect_*/,
// made by `admitgen fit samples/basotect_tuberlin/FILE.csv --columns f,_,_,_,_,re,im,_ --live 100`) so the test
// is quick.
#include "codegen/runtime_filter.hpp"
#include "core/text.hpp"
#include "checks/check_suite.hpp"
#include "emit/emit.hpp"
#include "io/check_input.hpp"
#include "io/check_report.hpp"
#include "io/model_block.hpp"
#include "io/fit_file.hpp"
#include "model/multipole.hpp"
#include "codegen/template_text.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <vector>

using namespace admitgen;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFs = 48000.0;
constexpr int kSettle = 48000;    // 1 s: the slowest pole of these fits (alpha = 12.8 1/s) decays by e^-12.8
constexpr int kMeasure = 24000;   // 0.5 s: tones on the 2 Hz grid fs/kMeasure, so the correlation has no leakage
constexpr double kAmplitude = 0.45;

/// Measured H at f (on the 2 Hz grid) of one node driven by kAmplitude·sin(2πfn/fs): correlation over kMeasure
/// samples after kSettle. `to_sample` / `to_value` convert the format's data (f32 values, Q1.31, Q1.15 scaled by
/// 2^-out_shift at the output).
template <typename Sample, typename Coeffs, typename ToSample, typename ToValue>
std::complex<double> measured_gain(const Coeffs& c, double f, ToSample to_sample, ToValue to_value) {
  codegen::RuntimeNode<Sample> node(c, static_cast<int>(kFs));
  std::vector<Sample> in(kSettle + kMeasure);
  for (std::size_t n = 0; n < in.size(); ++n) in[n] = to_sample(kAmplitude * std::sin(2 * kPi * f * double(n) / kFs));
  const std::vector<Sample> out = node.process(in);
  double s = 0.0, co = 0.0;
  for (int n = kSettle; n < kSettle + kMeasure; ++n) {
    const double y = to_value(out[static_cast<std::size_t>(n)]);
    s += y * std::sin(2 * kPi * f * n / kFs);
    co += y * std::cos(2 * kPi * f * n / kFs);
  }
  // y = A|H| sin(wn + phi): Σ y sin = A|H| cos(phi) N/2, Σ y cos = A|H| sin(phi) N/2.
  return std::complex<double>(s, co) / (kAmplitude * kMeasure / 2.0);
}

}  // namespace

TEST_CASE("emitted filters driven with tones match their continuous model in every format (four Basotect fits)") {
  // Tolerance per tone, from the arithmetic: the fidelity check bounds the coefficients' deviation by its
  // tolerance (0.5 %); rounding adds at most the kernel's noise floor N (codegen/fidelity.hpp) and, in fixed point,
  // the input's rounding (≤ 2^-(D+1) per sample, through ‖h‖₁); a bounded error e[n] moves the correlation estimate
  // by at most 2 max|e|/A. The settle leaves < e^-12 of a transient. So
  //   |H_measured − G|/|G| ≤ 0.005 + 2 (N + ‖h‖₁ 2^-(D+1)) / (A |G|) + 1e-5.
  const std::string tpl = codegen::load_template("", "admitgen_boundary.h.in");
  int tones = 0;
  for (const char* file : {"round_10cm", "round_5cm", "rect_10cm", "rect_5cm"}) {
    const std::string path = test::sample(std::string("fits/basotect_") + file + "/fit.json");
    const FitRecord fit = io::read_fit_file(path);
    for (const auto format : {codegen::Format::f32, codegen::Format::q31, codegen::Format::q15}) {
      codegen::EmitSettings s;
      s.fs_hz = {kFs};
      s.format = format;
      s.name = "wall";
      const emit::EmitResult e = emit::emit(fit, path, s, tpl, "wall.h");
      CAPTURE(file);
      CAPTURE(codegen::format_name(format));
      INFO(e.refusal("wall.h"));
      REQUIRE(e.safe());
      const codegen::EmittedRate& rate = e.emission.rates.front();
      const double lo = fit.input.f_min_hz, hi = fit.input.f_max_hz;
      for (int k = 0; k < 12; ++k) {
        const double f = 2.0 * std::round(0.5 * lo * std::pow(hi / lo, k / 11.0));
        const std::complex<double> g =
            evaluate_multipole(e.emission.surface.order, e.emission.surface.theta, Eigen::ArrayXd::Constant(1, 2 * kPi * f))[0];
        std::complex<double> h;
        double input_rounding = 0.0;
        if (format == codegen::Format::f32) {
          h = measured_gain<float>(rate.f32, f, [](double x) { return static_cast<float>(x); },
                                   [](float y) { return double(y); });
        } else if (format == codegen::Format::q31) {
          const int shift = rate.fixed->out_shift;
          h = measured_gain<std::int32_t>(
              *rate.fixed, f, [](double x) { return static_cast<std::int32_t>(std::lround(std::ldexp(x, 31))); },
              [shift](std::int32_t y) { return std::ldexp(double(y), shift - 31); });
          input_rounding = std::ldexp(1.0, -32);
        } else {
          const int shift = rate.fixed->out_shift;
          h = measured_gain<std::int16_t>(
              *rate.fixed, f, [](double x) { return static_cast<std::int16_t>(std::lround(std::ldexp(x, 15))); },
              [shift](std::int16_t y) { return std::ldexp(double(y), shift - 15); });
          input_rounding = std::ldexp(1.0, -16);
        }
        const double l1 = rate.fixed ? rate.fixed->l1_norm : rate.model.l1_norm();
        const double tol =
            0.005 + 2.0 * (rate.fidelity.noise_floor + l1 * input_rounding) / (kAmplitude * std::abs(g)) + 1e-5;
        CAPTURE(f);
        CHECK(std::abs(h - g) / std::abs(g) <= tol);
        ++tones;
      }
    }
  }
  CHECK(tones == 4 * 3 * 12);
}

TEST_CASE("fidelity: a q15 header whose output rounds to zero in band fails check, though it is safe") {
  // A nearly rigid wall: G = 0.01 + a pair at 20 kHz of quality factor 1000 with B/alpha = 1000 and C = -B alpha/beta
  // (G(0) = 0.01; |C| beta = B alpha: passive term by term). In band (50 Hz - 2 kHz) |G| is 0.011 - 0.2, but the
  // resonance makes the impulse response's L1 norm ~1300, so q15 needs out_shift 11: half the output's LSB,
  // 2^(11 - 16) = 0.031 for a full-scale input, exceeds |G| at the low end and a tone there comes out as zero.
  // Causal, stable, passive, in range, free of limit cycles: only fidelity can fail it.
  const Order o(0, 1);
  const double beta = 2 * kPi * 20000.0, alpha = beta / 1000.0, b = 1000.0 * alpha;
  codegen::EmissionSource src;
  src.surface = MultipoleSurface{o, (Eigen::VectorXd(5) << 0.01, b, -b * alpha / beta, alpha, beta).finished()};
  src.fit_name = "synthetic";
  for (int i = 0; i < 200; ++i) src.data_f_hz.push_back(50.0 * std::pow(40.0, i / 199.0));
  codegen::EmitSettings s;
  s.fs_hz = {96000.0};
  s.format = codegen::Format::q15;
  s.name = "wall";
  const emit::EmitResult r = emit::emit(src, s, codegen::load_template("", "admitgen_boundary.h.in"), "wall.h");
  const codegen::Emission& e = r.emission;
  const checks::CheckReport& report = r.report;
  REQUIRE(e.rates.front().fixed->out_shift >= 10);
  // Reference for "rounds to zero": |G(100 Hz)| · full scale < ½ output LSB, computed from the closed form.
  const double g100 = std::abs(evaluate_multipole(o, src.surface.theta, Eigen::ArrayXd::Constant(1, 2 * kPi * 100.0))[0]);
  REQUIRE(g100 < 0.5 * std::ldexp(1.0, e.rates.front().fixed->out_shift - 15));
  const auto failed = report.failed_checks();
  INFO(io::check_report_text(report));
  CHECK(failed == std::vector<std::string>{"fidelity"});
  CHECK_FALSE(r.safe());  // emit refuses it (with 32-bit coefficients too: the output scale is the same)
  CHECK(r.refusal("wall.h").find("fidelity") != std::string::npos);
  // And the kernel indeed outputs zero for a full-scale 100 Hz tone (the runtime's own q15 kernel).
  codegen::RuntimeNode<std::int16_t> node(*e.rates.front().fixed, 96000);
  std::vector<std::int16_t> in(96000);
  for (std::size_t n = 0; n < in.size(); ++n)
    in[n] = static_cast<std::int16_t>(std::lround(32767.0 * std::sin(2 * kPi * 100.0 * double(n) / 96000.0)));
  const auto out = node.process(in);
  int nonzero = 0;
  for (std::size_t n = 48000; n < out.size(); ++n) nonzero += out[n] != 0;
  CHECK(nonzero == 0);
}

// SPDX-License-Identifier: MIT
// Discretisation (codegen/discrete_model.hpp): PLRC baseline against docs/physics.md §1.3, the refit, folding,
// the realisation's internal consistency.
#include "codegen/discrete_model.hpp"
#include "core/errors.hpp"
#include "physics/multipole_surface.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

using namespace admitgen;
using namespace admitgen::codegen;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The reference Q1S1 fit committed for the runtime tests and samples.
MultipoleSurface reference_fit(std::vector<double>& f) {
  std::ifstream in(test::sample("fits/q1s1_reference.json"));
  const auto j = nlohmann::json::parse(in);
  for (const auto& v : j["predictive"]["f_hz"]) f.push_back(v.get<double>());
  return multipole_from_fit(j, "", Estimate::mean, "fit");
}

}  // namespace

TEST_CASE("PLRC baseline reproduces the docs/physics.md §1.3 error table for one real pole") {
  // λ = 2π·500 Hz, fs = 48 kHz: PLRC relative error 3.3e-4 at 0.01 fs, 3.3e-2 at 0.1 fs (table, [verified]).
  const Order order(1, 0);
  Eigen::VectorXd theta(3);
  theta << 0.0, 1000.0, 2 * kPi * 500.0;
  const double at_001 = discretise(order, theta, 48000.0, {480.0}).plrc_max_rel_error;
  const double at_01 = discretise(order, theta, 48000.0, {4800.0}).plrc_max_rel_error;
  CHECK(at_001 == doctest::Approx(3.3e-4).epsilon(0.05));  // table gives 2 digits
  CHECK(at_01 == doctest::Approx(3.3e-2).epsilon(0.05));
}

TEST_CASE("the refit removes the discretisation error at the data frequencies") {
  std::vector<double> f;
  const auto s = reference_fit(f);
  const DiscreteModel m = discretise(s.order, s.theta, 48000.0, f);
  // PLRC alone: 8.3e-2 (|G| is small near 100 Hz, relative error large); refit target 1e-5.
  CHECK(m.plrc_max_rel_error > 1e-2);
  CHECK(m.refit_max_rel_error <= 1e-5);
  // Independent evaluation: DTFT of the simulated impulse response equals response() (1e-12: the IR
  // is truncated where the slowest pole has decayed by 14 decades).
  const auto h = m.impulse_response(m.tail_samples(14.0));
  for (double fi : {100.0, 1600.0, 4000.0}) {
    std::complex<double> dtft = 0.0;
    for (std::size_t n = 0; n < h.size(); ++n) dtft += h[n] * std::polar(1.0, -2 * kPi * fi / 48000.0 * double(n));
    CHECK(std::abs(dtft - m.response(fi)) <= 1e-12 * std::abs(m.response(fi)) + 1e-14);
  }
  CHECK(h[0] == doctest::Approx(m.h0()).epsilon(1e-14));  // y^0 = h0 u^0 for an impulse
}

TEST_CASE("poles far above the band are folded into the FIR path - rates below the data are refused") {
  std::vector<double> f;
  const auto s = reference_fit(f);
  // 16 kHz: the 9.3 kHz real pole lies above Nyquist; folding it gives < 1 % where keeping it gives 25 %.
  const DiscreteModel m = discretise(s.order, s.theta, 16000.0, f);
  CHECK(m.folded.size() == 1);
  CHECK(m.real.empty());
  CHECK(m.refit_max_rel_error < 1e-2);
  CHECK_THROWS_AS(discretise(s.order, s.theta, 8000.0, f), InputError);  // 4 kHz data ≥ 0.45·8 kHz
}

TEST_CASE("slow poles: eps = 1 − e^{−λT} without cancellation") {
  const Order order(1, 0);
  Eigen::VectorXd theta(3);
  const double lam = 2 * kPi * 0.5, t = 1.0 / 48000.0;  // λT = 6.5e-5
  theta << 0.1, 1.0, lam;
  const DiscreteModel m = discretise(order, theta, 48000.0, {100.0, 200.0, 400.0});
  // series: λT − (λT)²/2 + (λT)³/6; relative precision of expm1 ≈ 1e-16
  const double x = lam * t;
  CHECK(m.real[0].eps == doctest::Approx(x - x * x / 2 + x * x * x / 6).epsilon(1e-15));
}

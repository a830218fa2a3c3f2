// SPDX-License-Identifier: MIT
/// @file
/// Shared fixtures of the physics tests: the air constants docs/materials.md uses for its derived numbers,
/// and small helpers on spectra.
#pragma once

#include "core/errors.hpp"
#include "physics/air.hpp"

#include <Eigen/Core>
#include <doctest/doctest.h>

#include <complex>
#include <string>
#include <vector>

namespace admitgen::test {

/// docs/materials.md §1: "ρ0 = 1.213 kg/m³, c0 = 343 m/s, η = 1.839e-5 Pa·s, Pr = 0.71, γ = 1.4, P0 = 101325 Pa".
inline Air materials_md_air() { return Air{20.0, 1.213, 343.0, 1.839e-5, 0.71, 1.4, 101325.0}; }

/// One frequency as a grid.
inline Eigen::ArrayXd at(double f_hz) { return Eigen::ArrayXd::Constant(1, f_hz); }

/// α = 1 − |R|², R = (1 − y)/(1 + y).
inline double absorption_of(std::complex<double> y) { return 1.0 - std::norm((1.0 - y) / (1.0 + y)); }

/// The message of the InputError that `action()` throws, or "no error".
template <class Action>
std::string input_error_of(Action&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// An input and a fragment of the InputError message it must produce.
struct ExpectedError {
  std::string input;
  std::string fragment;
};

/// Checks that parse(input) throws an InputError containing the fragment, for every case.
template <class Parse>
void check_input_errors(Parse parse, const std::vector<ExpectedError>& cases) {
  for (const auto& c : cases) {
    CAPTURE(c.input);
    const std::string message = input_error_of([&] { (void)parse(c.input); });
    CHECK_MESSAGE(message.find(c.fragment) != std::string::npos, message);
  }
}

}  // namespace admitgen::test

// SPDX-License-Identifier: MIT
/// @file
/// The real SISO state-space realisation of an emitted discrete filter (docs/physics.md §2.3); the container,
/// the continuous realisation and the bilinear map are in model/state_space.hpp.
#pragma once

#include "codegen/discrete_model.hpp"
#include "model/state_space.hpp"

namespace admitgen::checks {

/// Discrete realisation of the runtime's recursion (codegen/discrete_model.hpp), states = the
/// previous sample's values: real x^n = (1−ε) x^{n−1} + ε u^n, y += c x^n  →  A = 1−ε, B = ε, C = c(1−ε),
/// D = cε; pair ψ^n = π ψ^{n−1} + g u^n, y += 2 Re(c ψ^n); FIR taps d_1.. through a delay line (poles z = 0).
StateSpace discrete_realisation(const codegen::DiscreteModel& model);

}  // namespace admitgen::checks

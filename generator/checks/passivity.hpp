// SPDX-License-Identifier: MIT
/// @file
/// Exact passivity test of an emitted discrete filter: the continuous test of model/passivity.hpp applied
/// through the bilinear map z = (1 + s)/(1 − s) (checks/state_space.hpp), crossings at θ = 2 atan ω.
#pragma once

#include "codegen/discrete_model.hpp"
#include "model/passivity.hpp"

namespace admitgen::checks {

/// Emitted discrete filter H(e^{j2πf/fs}); frequencies in Hz, a band reaching Nyquist has hi = fs/2.
/// Requires every |z| < 1. Each pair's resonance is sampled densely (model/passivity.hpp, FeatureWindow);
/// `scan_minimum` false uses the coarser net of a certifier in a loop (whose result is certified again).
PassivityResult discrete_passivity(const codegen::DiscreteModel& model, bool scan_minimum = true);

}  // namespace admitgen::checks

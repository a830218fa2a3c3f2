// SPDX-License-Identifier: MIT
/// @file
/// Exact passivity test of an emitted discrete filter: the continuous test of model/passivity.hpp applied
/// through the bilinear map z = (1 + s)/(1 − s) (checks/state_space.hpp), crossings at θ = 2 atan ω.
#pragma once

#include "codegen/discrete_model.hpp"
#include "model/passivity.hpp"

namespace admitgen::checks {

/// Emitted discrete filter H(e^{j2πf/fs}); frequencies in Hz, a band reaching Nyquist has hi = fs/2.
/// Requires every |z| < 1. `scan_minimum` false skips the dense scan that only feeds min_re/min_at
/// outside the negative bands (the decision and the bands are the same; for certifiers in a loop).
PassivityResult discrete_passivity(const codegen::DiscreteModel& model, bool scan_minimum = true);

}  // namespace admitgen::checks

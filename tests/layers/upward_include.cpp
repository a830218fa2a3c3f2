// SPDX-License-Identifier: MIT
// Compiled as a source of the model layer (tests/layers/CMakeLists.txt): selection/ is above model/, so
// this include must not resolve. The CTest job layers.upward_include_fails_to_compile expects the error.
#include "model/order.hpp"
#include "selection/fit.hpp"

int admitgen_layer_probe_upward() { return 0; }

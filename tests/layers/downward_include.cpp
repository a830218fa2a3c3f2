// SPDX-License-Identifier: MIT
// The control of upward_include.cpp: the same model-layer source, including a layer below model/ (core/),
// must compile, so the other job's failure is the layering and not a broken probe.
#include "core/errors.hpp"
#include "model/order.hpp"

int admitgen_layer_probe_downward() { return 0; }

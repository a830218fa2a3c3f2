// SPDX-License-Identifier: MIT
// The control of json_outside_io.cpp: the same include in a source of the io layer must compile, so the
// other job's failure is the rule and not a broken probe.
#include <nlohmann/json.hpp>

int admitgen_layer_probe_json_in_io() { return static_cast<int>(nlohmann::json::array().size()); }

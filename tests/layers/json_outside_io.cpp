// SPDX-License-Identifier: MIT
// Compiled as a source of the codegen layer (tests/layers/CMakeLists.txt): nlohmann_json is the io layer's
// alone, so this include must stop the compilation. The CTest job layers.json_outside_io_fails_to_compile
// expects the #error of cmake/json_outside_io/nlohmann/json.hpp.
#include <nlohmann/json.hpp>

int admitgen_layer_probe_json_outside_io() { return 0; }

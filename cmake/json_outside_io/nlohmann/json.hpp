// SPDX-License-Identifier: MIT
// Found first by the sources of every layer of generator/ but io (cmake/AdmitgenLayers.cmake,
// admitgen_layer_json): nlohmann_json is linked to the io layer only, which reads and writes every JSON
// file into typed records (docs/architecture.md, "JSON only in io").
#error "nlohmann_json is the io layer's alone: read or write JSON in generator/io/ and pass a typed record (docs/architecture.md, JSON only in io)"

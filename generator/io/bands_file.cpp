// SPDX-License-Identifier: MIT
#include "io/bands_file.hpp"

#include "core/version.hpp"

#include <nlohmann/json.hpp>

namespace admitgen::io {
namespace {

using Json = nlohmann::ordered_json;

Json rows(const std::vector<codegen::BandAbsorption>& bands) {
  Json a = Json::array();
  for (const auto& b : bands)
    a.push_back({{"center_hz", b.center_hz}, {"lo_hz", b.lo_hz}, {"hi_hz", b.hi_hz}, {"alpha_normal", b.alpha_normal},
                 {"alpha_random", b.alpha_random}, {"in_data", b.in_data}});
  return a;
}

}  // namespace

std::string bands_text(const codegen::Emission& e) {
  const Json j{{"schema", "admitgen.bands/1"},
               {"version", kVersion},
               {"name", e.settings.name},
               {"order", e.surface.order.name()},
               {"input_sha256", e.input_sha256},
               {"method", "mean over 32 log-spaced frequencies per band; normal incidence 1-|R|^2, R=(1-G)/(1+G); "
                          "random incidence: locally reacting, London/Kuttruff closed form"},
               {"octave", rows(e.octave)},
               {"third_octave", rows(e.third_octave)}};
  return j.dump(2) + "\n";
}

}  // namespace admitgen::io

// SPDX-License-Identifier: MIT
#include "io/bands_file.hpp"

#include "core/version.hpp"

#include <fmt/format.h>
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

constexpr const char* kMethod =
    "mean over 32 log-spaced frequencies per band; normal incidence 1-|R|^2, R=(1-G)/(1+G); random incidence: "
    "locally reacting, London/Kuttruff closed form";

}  // namespace

std::string bands_text(const codegen::Emission& e) {
  const Json j{{"schema", "admitgen.bands/1"},
               {"version", kVersion},
               {"name", e.settings.name},
               {"order", e.surface.order.name()},
               {"input_sha256", e.input_sha256},
               {"method", kMethod},
               {"octave", rows(e.octave)},
               {"third_octave", rows(e.third_octave)}};
  return j.dump(2) + "\n";
}

std::string library_bands_text(const std::string& library, const std::vector<MaterialBands>& materials) {
  Json list = Json::array();
  for (const auto& m : materials) {
    Json j{{"name", m.material}, {"order", m.order}, {"input_sha256", m.input_sha256}};
    for (const auto& [name, bands] : m.sets) j[name] = rows(bands);
    list.push_back(std::move(j));
  }
  const Json j{{"schema", "admitgen.library-bands/1"},
               {"version", kVersion},
               {"library", library},
               {"method", kMethod},
               {"materials", std::move(list)}};
  return j.dump(2) + "\n";
}

std::string library_bands_csv(const std::vector<MaterialBands>& materials) {
  std::string out = "material,band_set,center_hz,lo_hz,hi_hz,alpha_normal,alpha_random,in_data\n";
  for (const auto& m : materials)
    for (const auto& [name, bands] : m.sets)
      for (const auto& b : bands)
        out += fmt::format("{},{},{},{},{},{},{},{}\n", m.material, name, b.center_hz, b.lo_hz, b.hi_hz, b.alpha_normal,
                           b.alpha_random, b.in_data ? 1 : 0);
  return out;
}

}  // namespace admitgen::io

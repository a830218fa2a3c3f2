// SPDX-License-Identifier: MIT
#include "io/priors_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace admitgen::io {

PriorRanges read_priors_file(const std::string& path) {
  const std::string text = read_bounded(path, kMaxDocumentBytes, "prior file");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number overflow (1e999)
    throw FileError(path, 0, fmt::format("not valid JSON: {}", e.what()));
  }
  if (!j.is_object()) throw FileError(path, 0, "expected a JSON object of {\"family\": [lo, hi]}");
  PriorRanges ranges = PriorRanges::table1();
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const auto& value = item.value();
    Range* range = ranges.find(key);
    if (range == nullptr) throw FileError(path, 0, "unknown prior key (expected G_inf, A, lambda, B, C, alpha, beta)", key);
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      throw FileError(path, 0, fmt::format("prior '{}' must be [lo, hi]", key), value.dump());
    *range = Range{value[0].get<double>(), value[1].get<double>()};
  }
  ranges.validate(path);
  return ranges;
}

}  // namespace admitgen::io

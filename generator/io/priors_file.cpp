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
  // "residues" first: it decides which keys may follow.
  if (j.contains("residues")) {
    const auto& kind = j["residues"];
    if (kind == "gaussian") {
      ranges.residues = ResiduePrior::gaussian;
    } else if (kind != "uniform") {
      throw FileError(path, 0, "prior 'residues' must be \"gaussian\" or \"uniform\"", kind.dump());
    }
  }
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const auto& value = item.value();
    if (key == "residues") continue;
    if (key == "admittance_scale") {
      if (ranges.residues != ResiduePrior::gaussian)
        throw FileError(path, 0, "'admittance_scale' needs \"residues\": \"gaussian\"", value.dump());
      if (!value.is_number()) throw FileError(path, 0, "'admittance_scale' must be a number", value.dump());
      ranges.admittance_scale = value.get<double>();
      continue;
    }
    Range* range = ranges.find(key);
    if (range == nullptr)
      throw FileError(path, 0,
                      "unknown prior key (expected G_inf, A, lambda, B, C, alpha, beta, residues, admittance_scale)", key);
    if (ranges.residues == ResiduePrior::gaussian && key != "lambda" && key != "alpha" && key != "beta")
      throw FileError(path, 0,
                      fmt::format("'{}' is a residue range, which the Gaussian residue prior has not (set "
                                  "admittance_scale instead, or \"residues\": \"uniform\")",
                                  key),
                      value.dump());
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      throw FileError(path, 0, fmt::format("prior '{}' must be [lo, hi]", key), value.dump());
    *range = Range{value[0].get<double>(), value[1].get<double>()};
  }
  ranges.validate(path);
  return ranges;
}

}  // namespace admitgen::io

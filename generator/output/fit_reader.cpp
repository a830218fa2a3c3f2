// SPDX-License-Identifier: MIT
#include "output/fit_reader.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"

#include <fmt/format.h>


namespace admitgen {

nlohmann::json read_fit_file(const std::string& path) {
  const std::string text = read_bounded(path, kMaxDocumentBytes, "fit");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number overflow (1e999)
    throw FileError(path, 0, fmt::format("not JSON ({})", e.what()));
  }
}

}  // namespace admitgen

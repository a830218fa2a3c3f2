#include "output/fit_reader.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <fstream>

namespace admitgen {

nlohmann::json read_fit_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, 0, "cannot read the fit");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw FileError(path, 0, fmt::format("not JSON ({})", e.what()));
  }
}

}  // namespace admitgen

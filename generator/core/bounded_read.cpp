// SPDX-License-Identifier: MIT
#include "core/bounded_read.hpp"

#include "core/errors.hpp"

#include <filesystem>
#include <fstream>

namespace admitgen {

std::string read_bounded(const std::string& path, std::size_t max_bytes, const char* what, const char* advice) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw FileError(path, 0, fmt::format("is a directory, not a {}", what));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, 0, fmt::format("cannot open {}", what));
  std::string text;
  char block[1 << 16];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      throw FileError(path, 0, fmt::format("larger than {} MiB, the most admitgen reads for a {}{}{}", max_bytes >> 20, what,
                                           advice != nullptr ? ": " : "", advice != nullptr ? advice : ""));
  }
  return text;
}

}  // namespace admitgen

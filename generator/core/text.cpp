// SPDX-License-Identifier: MIT
#include "core/text.hpp"

namespace admitgen {

std::string_view trim(std::string_view text, std::string_view characters) {
  const auto b = text.find_first_not_of(characters);
  if (b == std::string_view::npos) return {};
  return text.substr(b, text.find_last_not_of(characters) - b + 1);
}

}  // namespace admitgen

/// @file
/// Locale-independent parsing of one decimal number (std::from_chars), accepting a leading '+'.
#pragma once

#include <charconv>
#include <optional>
#include <string_view>

namespace admitgen {

/// The value if `text` is exactly one number (inf/nan spellings included: the caller rejects them).
inline std::optional<double> parse_double(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Locale-independent parsing of one decimal number (std::from_chars), accepting a leading '+' and,
/// for exports from locales that write them, a decimal comma.
#pragma once

#include <charconv>
#include <optional>
#include <string>
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

/// As parse_double, with `decimal` ('.' or ',') as the decimal separator. With ',' a '.' anywhere
/// (a thousands separator "1.234,5") is rejected rather than guessed.
inline std::optional<double> parse_double(std::string_view text, char decimal) {
  if (decimal == '.') return parse_double(text);
  if (text.find('.') != std::string_view::npos) return std::nullopt;
  std::string copy(text);
  const auto comma = copy.find(',');
  if (comma != std::string::npos) {
    if (copy.find(',', comma + 1) != std::string::npos) return std::nullopt;
    copy[comma] = '.';
  }
  return parse_double(copy);
}

}  // namespace admitgen

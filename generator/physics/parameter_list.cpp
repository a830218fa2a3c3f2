// SPDX-License-Identifier: MIT
#include "physics/parameter_list.hpp"

#include "core/errors.hpp"
#include "data/number_parsing.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace admitgen {
namespace {

struct Suffix {
  std::string_view text;
  double scale;
  Dimension dimension;
};

// Longest suffixes first, so "mm" is not read as "m".
constexpr Suffix kSuffixes[] = {{"mm", 1e-3, Dimension::length}, {"cm", 1e-2, Dimension::length},
                                {"um", 1e-6, Dimension::length}, {"m", 1.0, Dimension::length},
                                {"%", 1e-2, Dimension::ratio}};

std::string_view suffixes_of(Dimension d) {
  switch (d) {
    case Dimension::length: return " (metres; units m, cm, mm, um accepted)";
    case Dimension::ratio: return " (a fraction; '%' accepted)";
    case Dimension::number: return "";
  }
  return "";
}

}  // namespace

ParameterList::ParameterList(std::string context, std::string_view text) : context_(std::move(context)) {
  if (trim(text).empty()) return;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    const auto item = trim(text.substr(start, comma - start));
    const auto eq = item.find('=');
    if (eq == std::string_view::npos)
      throw InputError(error(fmt::format("'{}' is not key=value", item)));
    const std::string key(trim(item.substr(0, eq)));
    const std::string value(trim(item.substr(eq + 1)));
    if (key.empty() || value.empty()) throw InputError(error(fmt::format("'{}' is not key=value", item)));
    if (!values_.emplace(key, value).second) throw InputError(error(fmt::format("'{}' given twice", key)));
    order_.push_back(key);
    start = comma + 1;
  }
}

std::string ParameterList::error(const std::string& what) const { return fmt::format("{}: {}", context_, what); }

std::optional<std::string> ParameterList::text(const std::string& key) {
  asked_.push_back(key);
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

double ParameterList::number(const std::string& key, Dimension dimension) {
  const auto raw = text(key);
  if (!raw) throw InputError(error(fmt::format("missing parameter '{}'{}", key, suffixes_of(dimension))));
  std::string_view digits = *raw;
  double scale = 1.0;
  for (const auto& s : kSuffixes) {
    if (digits.size() > s.text.size() && digits.substr(digits.size() - s.text.size()) == s.text) {
      if (s.dimension != dimension)
        throw InputError(error(fmt::format("'{}={}': unit '{}' does not fit this parameter{}", key, *raw, s.text,
                                           suffixes_of(dimension))));
      digits = trim(digits.substr(0, digits.size() - s.text.size()));
      scale = s.scale;
      break;
    }
  }
  const auto value = parse_double(digits);
  if (!value || !std::isfinite(*value))
    throw InputError(error(fmt::format("'{}={}' is not a finite number{}", key, *raw, suffixes_of(dimension))));
  return *value * scale;
}

double ParameterList::positive(const std::string& key, Dimension dimension) {
  const double v = number(key, dimension);
  if (!(v > 0.0)) throw InputError(error(fmt::format("'{}' must be positive (got {})", key, v)));
  return v;
}

void ParameterList::finish() const {
  for (const auto& key : order_)
    if (std::find(asked_.begin(), asked_.end(), key) == asked_.end())
      throw InputError(error(fmt::format("unknown parameter '{}' (accepted: {})", key, fmt::join(asked_, ", "))));
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// The "key=value, key=value" lists inside a material SPEC (`miki(sigma=10000, d=50mm)`) and an
/// effect (`edge_gap:width_m=0.5mm,depth_m=0.05`), read the same way: every key at most once, every
/// key consumed (an unknown or misspelt key is an error that lists the accepted ones), numbers
/// finite, lengths with an optional unit (m, cm, mm, um) and ratios with an optional '%'.
#pragma once

#include "core/text.hpp"  // trim, used with parameter lists

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace admitgen {

/// What a value measures; decides which unit suffixes it accepts.
enum class Dimension {
  number,  ///< plain number, no suffix
  length,  ///< metres; suffixes m, cm, mm, um
  ratio,   ///< fraction; suffix % divides by 100
};

class ParameterList {
 public:
  /// Parses `text` ("" allowed). `context` names the owner in messages, e.g. "material 'miki(...)'".
  /// Throws InputError on a malformed item or a repeated key.
  ParameterList(std::string context, std::string_view text);

  /// The value of `key`; throws InputError if absent, not a finite number or with a wrong unit.
  double number(const std::string& key, Dimension dimension = Dimension::number);
  /// Same, and the value must be > 0.
  double positive(const std::string& key, Dimension dimension = Dimension::number);
  /// The raw text of `key` if present.
  std::optional<std::string> text(const std::string& key);
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  /// Keys in the order given.
  const std::vector<std::string>& keys() const { return order_; }

  /// Throws InputError naming the first key that no accessor asked for, and the keys that were.
  void finish() const;

  /// An InputError prefixed with the context.
  [[nodiscard]] std::string error(const std::string& what) const;

 private:
  std::string context_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> order_;
  mutable std::vector<std::string> asked_;
};

}  // namespace admitgen

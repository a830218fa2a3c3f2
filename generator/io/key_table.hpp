// SPDX-License-Identifier: MIT
/// @file
/// The keys of a file as its field list names them (io/record_fields.hpp), and their table as
/// docs/formats.md prints it: one row per object of the file, its path and its keys in file order.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace admitgen::io {

/// One key of a field list: its name, whether it may be absent or null, and the keys under it.
struct KeyNode {
  /// records: an array of objects; keyed: {name: value}; keyed_records: {name: object}
  enum class Shape { value, object, records, keyed, keyed_records };
  std::string key;
  bool optional = false;
  Shape shape = Shape::value;
  std::vector<KeyNode> children;
  bool nullable = false;
};

/// The rows of the key table of `keys` (the document's top-level keys): the path of each object ("" for the
/// document, "input", "models[]", "models[].parameters[]") and its keys, each `key`, followed by "?" when it
/// may be absent, " {}" or " [{}]" for an object or an array of objects (with rows of their own),
/// " {name: …}" for an object keyed by name, and " or null" when it may be null (" {name: {}}" when its values are objects, with a row of their
/// own: "parameter_summary{}").
std::vector<std::pair<std::string, std::string>> key_table_rows(const std::vector<KeyNode>& keys);

}  // namespace admitgen::io

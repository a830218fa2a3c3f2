// SPDX-License-Identifier: MIT
#include "io/key_table.hpp"

namespace admitgen::io {
namespace {

std::string key_cell(const KeyNode& k) {
  std::string s = "`" + k.key + "`";
  if (k.optional) s += "?";
  switch (k.shape) {
    case KeyNode::Shape::value: break;
    case KeyNode::Shape::object: s += " {}"; break;
    case KeyNode::Shape::records: s += " [{}]"; break;
    case KeyNode::Shape::keyed: s += " {name: …}"; break;
    case KeyNode::Shape::keyed_records: s += " {name: {}}"; break;
  }
  if (k.nullable) s += " or null";
  return s;
}

void add_rows(const std::string& path, const std::vector<KeyNode>& keys,
              std::vector<std::pair<std::string, std::string>>& rows) {
  std::string cell;
  for (const auto& k : keys) cell += (cell.empty() ? "" : ", ") + key_cell(k);
  rows.emplace_back(path, cell);
  for (const auto& k : keys) {
    const std::string sub = (path.empty() ? "" : path + ".") + k.key;
    if (k.shape == KeyNode::Shape::object) add_rows(sub, k.children, rows);
    if (k.shape == KeyNode::Shape::records) add_rows(sub + "[]", k.children, rows);
    if (k.shape == KeyNode::Shape::keyed_records) add_rows(sub + "{}", k.children, rows);
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> key_table_rows(const std::vector<KeyNode>& keys) {
  std::vector<std::pair<std::string, std::string>> rows;
  add_rows("", keys, rows);
  return rows;
}

}  // namespace admitgen::io

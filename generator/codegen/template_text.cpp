// SPDX-License-Identifier: MIT
#include "codegen/template_text.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace admitgen::codegen {
namespace {

using Scope = std::vector<const TemplateContext*>;

const std::string* find_value(const Scope& scope, const std::string& name) {
  for (auto it = scope.rbegin(); it != scope.rend(); ++it) {
    const auto v = (*it)->values.find(name);
    if (v != (*it)->values.end()) return &v->second;
  }
  return nullptr;
}

const std::vector<TemplateContext>* find_list(const Scope& scope, const std::string& name) {
  for (auto it = scope.rbegin(); it != scope.rend(); ++it) {
    const auto v = (*it)->lists.find(name);
    if (v != (*it)->lists.end()) return &v->second;
  }
  return nullptr;
}

/// Renders text[pos, end) into out; returns where a {{/name}} closing `open` was found (or end).
void render_range(const std::string& text, std::size_t pos, std::size_t end, Scope& scope, std::string& out) {
  while (pos < end) {
    const std::size_t open = text.find("{{", pos);
    if (open == std::string::npos || open >= end) {
      out.append(text, pos, end - pos);
      return;
    }
    out.append(text, pos, open - pos);
    const std::size_t close = text.find("}}", open);
    ADMITGEN_ENSURE(close != std::string::npos && close < end, "unterminated tag at offset {}", open);
    const std::string tag = text.substr(open + 2, close - open - 2);
    pos = close + 2;
    if (!tag.empty() && tag[0] == '#') {
      const std::string name = tag.substr(1), end_tag = "{{/" + name + "}}";
      // Find the matching close, allowing nested blocks of the same name.
      std::size_t depth = 1, scan = pos, block_end = std::string::npos;
      while (depth > 0) {
        const std::size_t next_open = text.find("{{#" + name + "}}", scan), next_close = text.find(end_tag, scan);
        ADMITGEN_ENSURE(next_close != std::string::npos && next_close < end, "block '{}' is not closed", name);
        if (next_open != std::string::npos && next_open < next_close) {
          ++depth;
          scan = next_open + name.size() + 5;
        } else {
          --depth;
          block_end = next_close;
          scan = next_close + end_tag.size();
        }
      }
      const auto* items = find_list(scope, name);
      ADMITGEN_ENSURE(items != nullptr, "template list '{}' is not defined", name);
      for (const auto& item : *items) {
        scope.push_back(&item);
        render_range(text, pos, block_end, scope, out);
        scope.pop_back();
      }
      pos = block_end + end_tag.size();
    } else {
      ADMITGEN_ENSURE(tag.empty() || tag[0] != '/', "stray closing tag '{}'", tag);
      const std::string* v = find_value(scope, tag);
      ADMITGEN_ENSURE(v != nullptr, "template value '{}' is not defined", tag);
      out += *v;
    }
  }
}

}  // namespace

std::string render_template(const std::string& text, const TemplateContext& context) {
  std::string out;
  Scope scope{&context};
  render_range(text, 0, text.size(), scope, out);
  return out;
}

std::string load_template(const std::string& explicit_dir, const std::string& file) {
  if (explicit_dir.empty()) {
    const std::string* text = embedded_template(file);
    ADMITGEN_ENSURE(text != nullptr, "no template {} is embedded", file);
    return *text;
  }
  const std::filesystem::path path = std::filesystem::path(explicit_dir) / file;
  std::ifstream in(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path) || !in)
    throw FileError(path.string(), 0, "cannot read the template (the templates directory must hold " + file + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace admitgen::codegen

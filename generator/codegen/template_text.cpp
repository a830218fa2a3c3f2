// SPDX-License-Identifier: MIT
#include "codegen/template_text.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <cstdlib>
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

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string render_template(const std::string& text, const TemplateContext& context) {
  std::string out;
  Scope scope{&context};
  render_range(text, 0, text.size(), scope, out);
  return out;
}

std::string load_template(const std::string& explicit_dir, const std::string& file) {
  namespace fs = std::filesystem;
  std::vector<fs::path> dirs;
  if (!explicit_dir.empty()) {
    dirs.emplace_back(explicit_dir);
  } else {
    if (const char* env = std::getenv("ADMITGEN_TEMPLATES")) dirs.emplace_back(env);
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share" / "admitgen" / "templates");
    dirs.push_back(fs::path(ADMITGEN_SOURCE_DIR) / "templates");
  }
  std::string searched;
  for (const auto& d : dirs) {
    const fs::path p = d / file;
    if (fs::is_regular_file(p)) return read_all(p);
    searched += (searched.empty() ? "" : ", ") + p.string();
  }
  throw InputError(fmt::format("template {} not found (searched {}); pass --templates DIR", file, searched));
}

}  // namespace admitgen::codegen

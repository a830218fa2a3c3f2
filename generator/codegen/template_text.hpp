// SPDX-License-Identifier: MIT
/// @file
/// The whole template language of templates/: {{name}} substitutes a value; {{#list}}…{{/list}} repeats
/// its block once per item of a list (an item sees its own values, then the enclosing ones). Nothing
/// else — names and numbers are computed in C++, the templates only place them (docs/runtime.md).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace admitgen::codegen {

struct TemplateContext {
  std::map<std::string, std::string> values;
  std::map<std::string, std::vector<TemplateContext>> lists;
};

/// Renders `text`; an unknown name or an unbalanced block is a template bug (InternalError).
std::string render_template(const std::string& text, const TemplateContext& context);

/// Template directory: `explicit_dir` if not empty, else $ADMITGEN_TEMPLATES, else
/// <executable>/../share/admitgen/templates (installed), else the source tree's templates/.
/// Reads `file` from it; throws InputError naming the places searched.
std::string load_template(const std::string& explicit_dir, const std::string& file);

}  // namespace admitgen::codegen

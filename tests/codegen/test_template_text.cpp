// SPDX-License-Identifier: MIT
// The header template compiled into admitgen (codegen/template_text.hpp): the embedded text is the
// source file templates/admitgen_boundary.h.in byte for byte (reference: that file, read here), and
// `--templates DIR` reads DIR's file instead.
#include "codegen/template_text.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>

using namespace admitgen;

namespace {

std::string source_template() {
  const std::filesystem::path samples = std::filesystem::path(test::sample("")).parent_path();
  return test::read_text((samples.parent_path() / "templates" / "admitgen_boundary.h.in").string());
}

}  // namespace

TEST_CASE("template: the embedded header template is the source file, byte for byte") {
  const std::string source = source_template();
  REQUIRE(source.size() > 1000);
  const std::string* embedded = codegen::embedded_template("admitgen_boundary.h.in");
  REQUIRE(embedded != nullptr);
  CHECK(*embedded == source);
  CHECK(codegen::load_template("", "admitgen_boundary.h.in") == source);
  CHECK(codegen::embedded_template("no_such_template.h.in") == nullptr);
}

TEST_CASE("template: a templates directory overrides the embedded text, and a missing file is an input error") {
  const std::string dir = test::scratch_dir("template_override");
  test::write_text(dir + "/admitgen_boundary.h.in", "/* {{name}} */\n");
  CHECK(codegen::load_template(dir, "admitgen_boundary.h.in") == "/* {{name}} */\n");
  const std::string empty = test::scratch_dir("template_override_empty");
  CHECK_THROWS_WITH_AS(codegen::load_template(empty, "admitgen_boundary.h.in"),
                       doctest::Contains("admitgen_boundary.h.in: cannot read the template"), FileError);
}

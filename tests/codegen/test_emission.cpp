// SPDX-License-Identifier: MIT
// Header generation (codegen/emission.hpp, template_text.hpp, band_absorption.hpp) and `admitgen emit`.
#include "io/fit_file.hpp"
#include "io/model_block.hpp"
#include "codegen/band_absorption.hpp"
#include "codegen/emission.hpp"
#include "codegen/template_text.hpp"
#include "core/errors.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace admitgen;
using namespace admitgen::codegen;

namespace {

FitRecord reference_json() { return io::read_fit_file(test::sample("fits/q1s1_reference.json")); }

}  // namespace

TEST_CASE("template language: substitution, loops with scope, errors for unknown names") {
  TemplateContext c;
  c.values["x"] = "X";
  c.lists["items"] = {TemplateContext{{{"v", "1"}}, {}}, TemplateContext{{{"v", "2"}}, {}}};
  CHECK(render_template("a{{x}}b", c) == "aXb");
  CHECK(render_template("{{#items}}[{{v}}{{x}}]{{/items}}", c) == "[1X][2X]");
  CHECK_THROWS_AS(render_template("{{nope}}", c), InternalError);
  CHECK_THROWS_AS(render_template("{{#items}}open", c), InternalError);
}

TEST_CASE("band absorption: normal-incidence and London/Kuttruff limits") {
  CHECK(alpha_normal({1.0, 0.0}) == doctest::Approx(1.0));  // matched: R = 0
  CHECK(alpha_normal({0.0, 0.3}) == doctest::Approx(0.0).epsilon(1e-12));  // purely reactive
  // docs/physics.md §4.2: maximum random-incidence absorption 0.9512 at ζ = 1.567 (real)
  CHECK(alpha_random({1.0 / 1.567, 0.0}) == doctest::Approx(0.9512).epsilon(2e-4));
}

TEST_CASE("emitted header: stamped, deterministic, machine-readable block reads back exactly") {
  EmitSettings s;
  s.fs_hz = {48000.0, 96000.0};
  s.format = Format::q31;
  s.name = "wall";
  s.estimate = Estimate::mean;  // the committed reference fit predates passive estimates
  const auto e = prepare_emission(reference_json(), "q1s1_reference.json", s);
  const std::string tpl = load_template("", "admitgen_boundary.h.in");
  const std::string h1 = io::header_text(e, tpl, "wall.h"), h2 = io::header_text(e, tpl, "wall.h");
  CHECK(h1 == h2);
  CHECK(h1.find("ADMITGEN_RT_ABI_VERSION != 1") != std::string::npos);
  CHECK(h1.find(e.input_sha256) != std::string::npos);
  CHECK(h1.find("fit seed 1") != std::string::npos);
  const auto back = io::read_emitted_header(h1, "wall.h");
  REQUIRE(back.rates.size() == 2);
  CHECK(back.format == Format::q31);
  CHECK(back.surface.order == e.surface.order);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& q = *back.rates[i].fixed;
    const auto& ref = *e.rates[i].fixed;
    CHECK(q.fir == ref.fir);
    CHECK(q.acc_shift == ref.acc_shift);
    CHECK(q.pair.front().p_i == ref.pair.front().p_i);
    CHECK(q.real.front().eps == ref.real.front().eps);
  }
  CHECK_THROWS_AS(io::read_emitted_header("/* nothing */", "x.h"), InputError);
}

TEST_CASE("emit settings are validated") {
  EmitSettings s;
  s.name = "wall";
  s.fs_hz = {44100.5};
  CHECK_THROWS_AS(prepare_emission(reference_json(), "f", s), InputError);
  s.fs_hz = {48000.0, 48000.0};
  CHECK_THROWS_AS(prepare_emission(reference_json(), "f", s), InputError);
  s.fs_hz = {48000.0};
  s.name = "9wall";
  CHECK_THROWS_AS(prepare_emission(reference_json(), "f", s), InputError);
}

TEST_CASE("admitgen emit: exit 2 and no output on bad input - f32 header with bands JSON") {
  const std::string dir = test::scratch_dir("emit_cli");
  const std::string fit = test::sample("fits/q1s1_reference.json");
  auto r = test::run_admitgen("emit '" + fit + "' --fs 8000 --format q31 --out " + dir + "/low.h");
  CHECK(r.exit_code == 2);
  CHECK(r.output.find("0.45 fs") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/low.h"));
  r = test::run_admitgen("emit '" + fit + "' --fs 48000 --format f32 --golden " + dir + "/g.txt --out " + dir + "/g.h");
  CHECK(r.exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(dir + "/g.h"));
  r = test::run_admitgen("emit " + dir + "/missing.json --fs 48000 --format f32 --out " + dir + "/m.h");
  CHECK(r.exit_code == 2);
  r = test::run_admitgen("emit '" + fit + "' --fs 48000 --format f32 --out " + dir + "/wall-48k.h --bands-json " + dir +
                         "/bands.json --quiet");
  REQUIRE(r.exit_code == 0);
  const std::string header = test::read_text(dir + "/wall-48k.h");
  CHECK(header.find("static const admitgen_rt_model_f32 wall_48k_48000") != std::string::npos);  // name from the file
  const auto bands = nlohmann::json::parse(test::read_text(dir + "/bands.json"));
  CHECK(bands["octave"].size() == 10);
  CHECK(bands["third_octave"].size() == 30);
}

// SPDX-License-Identifier: MIT
// `admitgen check` on a catalogue of deliberately broken files, end to end: every file that parses is checked
// and exits 1 naming the failing check (and, for causality, the offending parameter); every file that
// cannot be read exits 2. emit refuses the same non-causal fits with the same named reason.
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <functional>

using namespace admitgen;

namespace {

nlohmann::json sample_fit(const std::string& relative) {
  std::ifstream in(test::sample(relative));
  return nlohmann::json::parse(in);
}

/// Sets `field` ("mean" or "max_likelihood") of parameter `name` in the selected order's summary.
void set_parameter(nlohmann::json& fit, const std::string& name, double value, const char* field = "mean") {
  bool found = false;
  for (auto& p : fit["parameters"])
    if (p["name"] == name) p[field] = value, found = true;
  REQUIRE(found);
}

/// Gives the selected order a passive estimate (the posterior means, in models[].passive_estimate.parameters
/// {name: value}; the other members as io/fit_file.hpp requires them) with `name` set to `value`.
void set_passive(nlohmann::json& fit, const std::string& name, double value) {
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& p : fit["parameters"]) parameters[p["name"].get<std::string>()] = p["mean"];
  REQUIRE(parameters.contains(name));
  parameters[name] = value;
  for (auto& m : fit["models"])
    if (m["order"] == fit["selected"]["order"]) {
      m["passive_estimate"] = {{"poles_from", "test"},
                               {"sample_rank", 0},
                               {"residues", "test"},
                               {"parameters", parameters},
                               {"log_likelihood", 0.0},
                               {"relative_rms_residual", 0.0},
                               {"delta_log_likelihood_vs_best_sample", 0.0},
                               {"best_sample_relative_rms_residual", 0.0},
                               {"certified_passive", false},
                               {"min_re_G", 0.0},
                               {"constraint_rounds", 0}};
      return;
    }
  FAIL("no selected model");
}

/// Replaces the first occurrence of `from` after `after` in `text`.
std::string replace_after(std::string text, const std::string& after, const std::string& from, const std::string& to) {
  const auto at = text.find(from, text.find(after));
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

struct Broken {
  std::string name;
  std::string text;
  std::string failing_check;  ///< named in the output
  std::string detail;         ///< also in the output (the offending parameter), may be empty
  std::string args = "";      ///< extra check options
};

}  // namespace

TEST_CASE("check catalogue: broken fit.json and headers exit 1 naming the check, unreadable files exit 2") {
  const std::string dir = test::scratch_dir("check_exit_catalogue");
  const auto reference = sample_fit("fits/q1s1_reference.json");  // Q1S1, no passive estimate: mean checked
  std::vector<Broken> broken;
  const auto fit_with = [&](const std::function<void(nlohmann::json&)>& edit, nlohmann::json fit) {
    edit(fit);
    return fit.dump(1);
  };
  broken.push_back({"negative_lambda.json", fit_with([](auto& f) { set_parameter(f, "lambda_1", -120.0); }, reference),
                    "causality", "lambda_1 = -120"});
  broken.push_back({"negative_alpha.json", fit_with([](auto& f) { set_parameter(f, "alpha_1", -35.0); }, reference),
                    "causality", "alpha_1 = -35"});
  broken.push_back({"zero_alpha.json", fit_with([](auto& f) { set_parameter(f, "alpha_1", 0.0); }, reference),
                    "causality", "alpha_1 = 0 1/s is not positive"});
  broken.push_back({"zero_lambda.json", fit_with([](auto& f) { set_parameter(f, "lambda_1", 0.0); }, reference),
                    "causality", "lambda_1 = 0 1/s is not positive"});
  broken.push_back({"negative_lambda_ml.json",
                    fit_with([](auto& f) { set_parameter(f, "lambda_1", -1.0, "max_likelihood"); }, reference), "causality",
                    "lambda_1 = -1", "--estimate max_likelihood"});
  broken.push_back({"negative_g_inf.json", fit_with([](auto& f) { set_parameter(f, "G_inf", -0.05); }, reference),
                    "passivity_continuous", ""});
  broken.push_back({"passive_estimate_negative_alpha.json",
                    fit_with([](auto& f) { set_passive(f, "alpha_1", -12.5); }, reference), "causality", "alpha_1 = -12.5"});
  broken.push_back({"passive_estimate_negative_g_inf.json",
                    fit_with([](auto& f) { set_passive(f, "G_inf", -0.5); }, reference), "passivity_continuous", ""});

  // Headers emitted from the reference fit, then edited.
  const std::string fit_path = test::sample("fits/q1s1_reference.json");
  const auto emit = [&](const std::string& name, const std::string& args) {
    const auto r = test::run_admitgen(fmt::format("emit '{}' --estimate mean --out {}/{} --quiet {}", fit_path, dir, name, args));
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    return test::read_text(dir + "/" + name);
  };
  const std::string q31 = emit("q31.h", "--fs 48000 --format q31");
  const std::string f32 = emit("f32.h", "--fs 48000 --format f32");
  const auto theta = reference["parameters"];  // G_inf, A_1, lambda_1, B_1, C_1, alpha_1, beta_1 (means)
  const auto block_value = [&](const std::string& header, int index) {
    const auto begin = header.find("admitgen:model") + std::string("admitgen:model").size();
    const auto block = nlohmann::json::parse(header.substr(begin, header.find("admitgen:end") - begin));
    return fmt::format("{}", block["continuous"]["theta"][static_cast<std::size_t>(index)].get<double>());
  };
  broken.push_back({"negative_lambda_q31.h",
                    replace_after(q31, "\"theta\":", block_value(q31, 2), "-" + block_value(q31, 2)), "causality", "lambda_1 = -"});
  broken.push_back({"negative_alpha_f32.h",
                    replace_after(f32, "\"theta\":", block_value(f32, 5), "-" + block_value(f32, 5)), "causality", "alpha_1 = -"});
  broken.push_back({"negative_g_inf_f32.h",
                    replace_after(f32, "\"theta\":", block_value(f32, 0), "-" + block_value(f32, 0)), "passivity_continuous", ""});
  // A real pole's q31 eps mantissa made negative (|z| > 1): every check still runs and reports (the headroom
  // check once ended in an internal error computing the L1 norm of the unstable filter).
  broken.push_back({"pole_outside_q31.h", replace_after(q31, "\"q31\":{", "\"real\":[[", "\"real\":[[-"),
                    "discrete_stability", "outside the unit circle"});
  {  // a C table edited after emission: the first FIR tap of the q31 table
    const auto at = q31.find("q31_48000_fir[");
    REQUIRE(at != std::string::npos);
    const auto open = q31.find('{', at), comma = q31.find(',', open);
    std::string h = q31;
    const std::string tap = h.substr(open + 1, comma - open - 1);  // "\n  51274237"
    h.replace(open + 1, comma - open - 1, fmt::format("\n  {}", std::stol(tap) + 1000));
    broken.push_back({"edited_table_q31.h", h, "header_integrity", ""});
  }
  {  // an unsafe filter written with --allow-unsafe: 6 taps at 16 kHz cancel in float (test_check_cli.cpp)
    const auto r = test::run_admitgen(fmt::format("emit '{}' --fs 16000 --fir-taps 5 --format f32 --allow-unsafe --out {}/w16.h",
                                                  fit_path, dir));
    REQUIRE(r.exit_code == 0);
    broken.push_back({"allow_unsafe_f32_16k.h", test::read_text(dir + "/w16.h"), "passivity_discrete", ""});
  }
  REQUIRE(broken.size() >= 12);
  for (const auto& b : broken) {
    CAPTURE(b.name);
    test::write_text(dir + "/" + b.name, b.text);
    const auto r = test::run_admitgen(fmt::format("check {}/{} {}", dir, b.name, b.args));
    CHECK_MESSAGE(r.exit_code == 1, r.output);
    CHECK_MESSAGE(r.output.find("FAIL " + b.failing_check) != std::string::npos, r.output);
    if (!b.detail.empty()) CHECK_MESSAGE(r.output.find(b.detail) != std::string::npos, r.output);
  }

  // emit refuses the non-causal fits, naming the same check and parameter, exit 1, nothing written.
  for (const std::string name : {"negative_lambda.json", "zero_alpha.json", "passive_estimate_negative_alpha.json"}) {
    CAPTURE(name);
    const auto expected = std::find_if(broken.begin(), broken.end(), [&](const Broken& b) { return b.name == name; });
    const auto r = test::run_admitgen(fmt::format("emit {}/{} --estimate {} --fs 48000 --format f32 --out {}/refused.h", dir, name,
                                                  name.rfind("passive", 0) == 0 ? "passive" : "mean", dir));
    CHECK_MESSAGE(r.exit_code == 1, r.output);
    CHECK(r.output.find("check 'causality' fails") != std::string::npos);
    CHECK(r.output.find(expected->detail) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir + "/refused.h"));
  }

  // Unreadable: exit 2, the file named.
  const std::vector<std::pair<std::string, std::string>> unreadable = {
      {"empty.json", ""},
      {"truncated.json", reference.dump(1).substr(0, 400)},
      {"other_schema.json", R"({"schema": "admitgen.emit/1", "models": []})"},
      {"schema_not_a_string.json", R"({"schema": ["admitgen.fit/1"]})"},  // found by fuzzing (was exit 3)
      {"missing_beta.json", fit_with([](auto& f) {
         auto& ps = f["parameters"];
         ps.erase(ps.size() - 1);  // beta_1
       }, reference)},
      {"string_parameter.json", fit_with([](auto& f) { f["parameters"][2]["mean"] = "fast"; }, reference)},
      {"unknown_order.json", fit_with([](auto& f) { f["selected"]["order"] = "Q9S9"; }, reference)},
      {"short_theta.h", replace_after(q31, "\"theta\":[", block_value(q31, 0) + ",", "")},
      {"float_mantissa.h", replace_after(q31, "\"q31\":{", "\"fir\":[", "\"fir\":[1.5e20,")},  // found by fuzzing
      {"huge_shift.h", replace_after(q31, "\"q31\":{", "\"acc_shift\":", "\"acc_shift\":9")},  // 930: outside 1..62
      {"block_not_json.h", "/* admitgen:model {\"format\": \"q31\", admitgen:end */\n"},
      {"binary.h", std::string("\x7f" "ELF\x02\x01\x01\0\0\0", 10)},
  };
  for (const auto& [name, text] : unreadable) {
    CAPTURE(name);
    test::write_text(dir + "/" + name, text);
    const auto r = test::run_admitgen(fmt::format("check {}/{}", dir, name));
    CHECK_MESSAGE(r.exit_code == 2, r.output);
    CHECK(r.output.find(name) != std::string::npos);
  }
  CHECK(test::run_admitgen(fmt::format("check {}/does_not_exist.json", dir)).exit_code == 2);
  CHECK(test::run_admitgen(fmt::format("check {}", dir)).exit_code == 2);  // a directory
}

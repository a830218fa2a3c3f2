// SPDX-License-Identifier: MIT
// The one reader and writer of fit.json and diagnosis.json (io/fit_file.hpp, io/diagnosis_file.hpp,
// docs/formats.md): a bundled file read into its record and written again gives the same bytes, and every
// malformed document is refused naming the file, the key and the value.
#include "core/errors.hpp"
#include "io/diagnosis_file.hpp"
#include "io/fit_file.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

using namespace admitgen;

namespace {

/// Fits written by `admitgen fit` (the passivity demo's fit was edited by hand, below).
const std::vector<std::string> kFits = {"fits/q1s1_reference.json", "fits/basotect_round_10cm_passive/fit.json",
                                        "synthetic/glass_beads_40mm_fit/fit.json",
                                        "synthetic/mpp_three_layer_fit/fit.json"};

/// `text` with the first occurrence of `from` replaced by `to` (which must occur).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE_MESSAGE(at != std::string::npos, from);
  return text.replace(at, from.size(), to);
}

/// The message of the FileError `f` throws ("" if it throws none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("fit.json: every bundled fit reads into a record that writes back byte for byte") {
  // The bundled fits were written by earlier versions of the writer (some lack keys added since): the
  // record keeps what each holds, in the writer's key order, and numbers in shortest round-trip form.
  for (const auto& name : kFits) {
    CAPTURE(name);
    const std::string text = test::read_text(test::sample(name));
    const FitRecord fit = io::parse_fit(text, name);
    CHECK(io::fit_text(fit) == text);
    CHECK(fit.model() != nullptr);
    CHECK(fit.model()->order == fit.selected_order);
  }
  // A fit saved by another JSON writer (other digits for the same doubles, no final newline) reads into the
  // same record its rewrite reads into: the numbers survive exactly.
  const std::string edited = test::read_text(test::sample("passivity_demo/nonpassive_fit.json"));
  const std::string rewritten = io::fit_text(io::parse_fit(edited, "demo"));
  CHECK(io::fit_text(io::parse_fit(rewritten, "demo")) == rewritten);
  CHECK(io::parse_fit(rewritten, "demo").models.at(0).log_evidence == io::parse_fit(edited, "demo").models.at(0).log_evidence);
}

TEST_CASE("fit.json: malformed documents are refused naming file, key and value") {
  const std::string good = test::read_text(test::sample("fits/q1s1_reference.json"));
  const auto error = [](const std::string& text) { return error_of([&] { (void)io::parse_fit(text, "f.json"); }); };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"not json", "f.json: not JSON"},
      {R"({"schema": "admitgen.emit/1"})", "f.json: JSON but not an admitgen fit (schema admitgen.fit/1)"},
      {R"({"schema": ["admitgen.fit/1"]})", "f.json: JSON but not an admitgen fit"},
      {replaced(good, "\"live\": 500,", ""), "f.json: missing key 'settings.live'"},
      {replaced(good, "\"seed\": 1,", "\"seed\": -1,"), "f.json: expected a non-negative integer at key 'settings.seed' (value '-1')"},
      {replaced(good, "\"qmax\": 1,", "\"qmax\": 1.5,"), "f.json: expected an integer at key 'settings.qmax' (value '1.5')"},
      {replaced(good, "\"mean\": ", "\"mean\": \"fast\", \"x\": "),
       "f.json: expected a number at key 'models[0].parameters[0].mean' (value '\"fast\"')"},
      {replaced(good, "\"points\": 200,", "\"points\": 200, \"colour\": \"red\","), "f.json: unknown key 'input.colour'"},
      {replaced(good, "\"slices\": \"3 + dim\"", "\"slices\": \"many\""),
       "f.json: expected a number of slices or \"3 + dim\" at key 'settings.sampler.slices' (value '\"many\"')"},
      {replaced(good, "\"order\": \"Q0S0\"", "\"order\": \"fast\""),
       "f.json: expected an order QxSy at key 'models[0].order' (value '\"fast\"')"},
      {replaced(good, "\"rule\": \"best evidence\"", "\"rule\": \"best evidence\", \"extra\": 1"), "f.json: unknown key 'selected.extra'"},
  };
  for (const auto& [text, message] : cases) {
    CAPTURE(message);
    CHECK(error(text).find(message) == 0);
  }
  // The selected order must be one of the fitted models.
  const std::string unknown_order = error(replaced(good, "\"order\": \"Q1S1\",\n    \"rule\"", "\"order\": \"Q9S9\",\n    \"rule\""));
  CHECK(unknown_order == "f.json: the selected order is not among the fitted models at key 'selected.order' (value '\"Q9S9\"')");
}

TEST_CASE("fit.json: a newer admitgen may add keys (skipped), an equal or older one may not") {
  const std::string good = test::read_text(test::sample("fits/q1s1_reference.json"));
  const std::string added = replaced(good, "\"points\": 200,", "\"points\": 200, \"colour\": \"red\",");
  CHECK(error_of([&] { (void)io::parse_fit(added, "f.json"); }).find("unknown key 'input.colour'") != std::string::npos);
  const std::string newer = replaced(added, "\"version\": \"0.1.0\"", "\"version\": \"99.0.0\"");
  CHECK(io::parse_fit(newer, "f.json").input.points == 200);
  // A missing key stays an error whoever wrote the file.
  const std::string newer_missing = replaced(newer, "\"points\": 200,", "");
  CHECK(error_of([&] { (void)io::parse_fit(newer_missing, "f.json"); }) == "f.json: missing key 'input.points'");
}

TEST_CASE("diagnosis.json: the bundled diagnoses (schema /2) read as the current schema and write back byte for byte") {
  for (const char* name : {"diagnosis/round_vs_rect_5cm/diagnosis.json", "diagnosis/round_vs_rect_10cm/diagnosis.json"}) {
    CAPTURE(name);
    const std::string text = test::read_text(test::sample(name));
    REQUIRE(text.find("\"schema\": \"admitgen.diagnosis/2\"") != std::string::npos);
    const auto d = io::parse_diagnosis(text, name);
    CHECK(d.schema == "admitgen.diagnosis/3");
    // What /2 lacks stays empty: no shares, no main cause, no dropped member.
    CHECK(d.verdict.shares.empty());
    CHECK_FALSE(d.verdict.main_cause);
    CHECK(d.verdict.dropped.empty());
    CHECK_FALSE(d.verdict.explanation.empty());
    // Written as /3, the text reads back into the same record and writes back byte for byte.
    const std::string current = io::diagnosis_text(d);
    CHECK(io::diagnosis_text(io::parse_diagnosis(current, name)) == current);
    CHECK_FALSE(d.gap.bands.empty());
  }
  const std::string good =
      io::diagnosis_text(io::parse_diagnosis(test::read_text(test::sample("diagnosis/round_vs_rect_5cm/diagnosis.json")), "d"));
  const auto error = [](const std::string& text) { return error_of([&] { (void)io::parse_diagnosis(text, "d.json"); }); };
  CHECK(error(R"({"schema": "admitgen.fit/1"})") == "d.json: JSON but not an admitgen diagnosis (schema admitgen.diagnosis/3)");
  CHECK(error(replaced(good, "\"log_evidence_none\"", "\"log_evidence_nothing\"")) == "d.json: missing key 'log_evidence_none'");
  CHECK(error(replaced(good, "\"white\": ", "\"white\": 1, \"w\": ")) ==
        "d.json: expected true or false at key 'gap.whiteness.white' (value '1')");
  // A /3 file must hold the new keys.
  CHECK(error(replaced(good, "\"main_cause\": null,", "")) == "d.json: missing key 'verdict.main_cause'");
}

TEST_CASE("diagnosis.json: shares, the main cause and dropped members are written and read back") {
  const std::string name = "diagnosis/round_vs_rect_5cm/diagnosis.json";
  auto d = io::parse_diagnosis(test::read_text(test::sample(name)), name);
  REQUIRE(d.verdict.explanation.size() == 3);
  d.verdict.shares = {{d.verdict.explanation[1].effect, 1, 0.625}, {d.verdict.explanation[0].effect, 0, 0.0625},
                      {d.verdict.explanation[2].effect, 2, -0.015625}};
  d.verdict.main_cause = d.verdict.shares.front();
  d.verdict.dropped = {{"material", std::string("1.d"), 12.5, "within the margin"}, {"temperature", std::nullopt, -3.25, "r"}};
  const std::string text = io::diagnosis_text(d);
  CHECK(text.find("\"main_cause\": {\n      \"effect\": \"" + d.verdict.explanation[1].effect +
                  "\",\n      \"member\": 1,\n      \"share\": 0.625\n    }") != std::string::npos);
  CHECK(text.find("\"parameter\": \"1.d\"") != std::string::npos);
  const auto back = io::parse_diagnosis(text, "d.json");
  REQUIRE(back.verdict.shares.size() == 3);
  CHECK(back.verdict.shares[2].member == 2);
  CHECK(back.verdict.shares[2].share == -0.015625);
  REQUIRE(back.verdict.main_cause);
  CHECK(back.verdict.main_cause->share == 0.625);
  REQUIRE(back.verdict.dropped.size() == 2);
  CHECK(back.verdict.dropped[0].parameter == std::optional<std::string>("1.d"));
  CHECK_FALSE(back.verdict.dropped[1].parameter);
  CHECK(back.verdict.dropped[1].log_bayes_factor_deciban == -3.25);
  CHECK(io::diagnosis_text(back) == text);
}

TEST_CASE("diagnosis.json: an admitgen.diagnosis/1 file is read, its verdict effect becoming the explanation") {
  const std::string name = "diagnosis/round_vs_rect_5cm/diagnosis.json";
  const auto current = io::parse_diagnosis(test::read_text(test::sample(name)), name);
  // The /1 form of the same diagnosis: its schema, and a verdict without "explanation".
  auto old = current;
  old.schema = "admitgen.diagnosis/1";
  old.verdict.effect = current.effects.at(1).effect;  // a /1 verdict named one effect (not necessarily the first)
  std::string text = io::diagnosis_text(old);
  const auto start = text.find("\"explanation\": [");
  REQUIRE(start != std::string::npos);
  const auto end = text.find("\"shrink\":", start);
  text.erase(start, end - start);
  const auto v1 = io::parse_diagnosis(text, "old.json");
  CHECK(v1.schema == "admitgen.diagnosis/3");
  REQUIRE(v1.verdict.explanation.size() == 1);
  CHECK(v1.verdict.explanation[0].effect == current.effects[1].effect);
  CHECK(v1.verdict.explanation[0].parameters == current.effects[1].parameters);
  CHECK(v1.verdict.explanation[0].shrink_added == current.verdict.shrink);
  old.verdict.effect = "none";
  std::string none = io::diagnosis_text(old);
  none.erase(none.find("\"explanation\": ["), none.find("\"shrink\":", none.find("\"explanation\": [")) - none.find("\"explanation\": ["));
  CHECK(io::parse_diagnosis(none, "old.json").verdict.explanation.empty());
}

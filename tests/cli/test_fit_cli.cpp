// SPDX-License-Identifier: MIT
// The `fit` command end to end: bad inputs (docs/cli.md exit codes), determinism across
// thread counts, and quiet output when stderr is not a terminal.
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

using namespace admitgen::test;
namespace fs = std::filesystem;

namespace {

struct BadInput {
  const char* name;
  const char* data;    ///< file content; nullptr = do not create the file
  const char* extra;   ///< extra command-line options
  const char* expect;  ///< text the error message must contain
};

const std::string kGood = "100,0.1,0.2\n200,0.2,0.3\n300,0.3,0.4\n400,0.35,0.4\n500,0.4,0.41\n600,0.45,0.4\n";

}  // namespace

TEST_CASE("fit: every bad input exits 2 with a message naming the problem and writes nothing") {
  const std::vector<BadInput> cases{
      {"empty file", "", "", "no data rows"},
      {"comments only", "# nothing\n# here\n", "", "no data rows"},
      {"one point", "100,0.1,0.2\n", "", "only 1 data point"},
      {"NaN", "100,0.1,0.2\n200,nan,0.3\n300,0.3,0.4\n", "", ":2: column 2 (re) is not finite (value 'nan')"},
      {"infinity", "100,0.1,0.2\n200,0.2,inf\n300,0.3,0.4\n", "", ":2: column 3 (im) is not finite"},
      {"negative frequency", "100,0.1,0.2\n-200,0.2,0.3\n300,0.3,0.4\n", "", ":2: frequency must be positive (Hz) (value '-200')"},
      {"zero frequency", "0,0.1,0.2\n200,0.2,0.3\n300,0.3,0.4\n", "", ":1: frequency must be positive"},
      {"duplicate frequency", "100,0.1,0.2\n200,0.2,0.3\n200,0.3,0.4\n", "", ":3: duplicate frequency (also on line 2)"},
      {"text in a number field", "100,0.1,0.2\n200,abc,0.3\n300,0.3,0.4\n", "", ":2: column 2 (re) is not a number (value 'abc')"},
      {"wrong column count", "100,0.1,0.2\n200,0.2\n300,0.3,0.4\n", "", ":2: expected 3 columns, found 2"},
      {"empty field", "100,0.1,0.2\n200,,0.3\n300,0.3,0.4\n", "", ":2: column 2 (re) is not a number"},
      {"missing file", nullptr, "", "cannot open data file"},
      {"SI values read as normalised", "100,400,200\n200,410,190\n300,420,180\n", "", "look like SI units"},
      {"frequencies in kHz", "0.1,0.1,0.2\n0.2,0.2,0.3\n0.3,0.3,0.4\n", "", "expected Hz (not kHz)"},
      {"band outside the data", kGood.c_str(), "--band 5000:6000", "no data inside --band"},
      {"reversed band", kGood.c_str(), "--band 1000:500", "FMAX must exceed FMIN"},
      {"qmax -1", kGood.c_str(), "--qmax -1", "--qmax"},
      {"live 0", kGood.c_str(), "--live 0", "--live"},
      {"bad selection rule", kGood.c_str(), "--select cheapest:-3", "--select"},
      {"bad columns spec", kGood.c_str(), "--columns f,re", "--columns 'f,re'"},
      {"unknown quantity", kGood.c_str(), "--quantity pressure", "--quantity"},
      {"rho-c with a reflection factor", kGood.c_str(), "--quantity reflection --rho-c 413", "--rho-c does not apply"},
      {"non-positive rho-c", kGood.c_str(), "--rho-c -5", "--rho-c must be a positive number"},
      {"missing prior file", kGood.c_str(), "--priors /nonexistent/p.json", "cannot open prior file"},
      {"too few points for the grid", kGood.c_str(), "--qmax 3 --smax 3", "Q3S3 has 19 parameters but the data hold only K = 12"},
  };
  const std::string dir = scratch_dir("fit_bad_inputs");
  int index = 0;
  for (const BadInput& c : cases) {
    const std::string data = dir + "/case" + std::to_string(index) + ".csv";
    const std::string out = dir + "/out" + std::to_string(index++);
    if (c.data != nullptr) write_text(data, c.data);
    const auto r = run_admitgen("fit '" + data + "' --out '" + out + "' " + c.extra);
    INFO(std::string(c.name), "\n", r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(c.expect) != std::string::npos);
    CHECK(!fs::exists(out + "/fit.json"));
  }

  // Output location problems: a regular file where the directory should be, and a path below a file.
  write_text(dir + "/good.csv", kGood);
  write_text(dir + "/a_file", "x");
  for (const std::string& out : {dir + "/a_file", dir + "/a_file/sub"}) {
    const auto r = run_admitgen("fit '" + dir + "/good.csv' --qmax 0 --smax 0 --out '" + out + "'");
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("output") != std::string::npos);
  }
  // Nothing half-written anywhere in the scratch area.
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    CHECK(entry.path().string().find(".tmp.") == std::string::npos);
}

TEST_CASE("fit: byte-identical fit.json for --threads 1 and 2 (timing fields aside) - quiet when not a terminal") {
  const std::string dir = scratch_dir("fit_determinism");
  const std::string data = sample("reference/q1s1_sigma0.01.csv");
  std::vector<std::string> outputs;
  for (const char* threads : {"1", "2", "2"}) {
    const std::string out = dir + "/t" + threads + std::to_string(outputs.size());
    const auto r = run_admitgen("fit '" + data + "' --qmax 1 --smax 1 --live 60 --seed 4 --threads " +
                                threads + " --out '" + out + "'");
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find('\r') == std::string::npos);  // no progress line when stderr is a pipe
    CHECK(r.output.find("Q1S1") != std::string::npos);  // the summary table is printed
    // Nothing in fit.json measures time (run times are printed, not stored): byte for byte.
    outputs.push_back(read_text(out + "/fit.json"));
  }
  CHECK(outputs[0].find("\"schema\": \"admitgen.fit/1\"") != std::string::npos);
  CHECK(outputs[0] == outputs[1]);
  CHECK(outputs[1] == outputs[2]);
  const auto quiet = run_admitgen("fit '" + data + "' --qmax 0 --smax 1 --live 30 --quiet --out '" + dir + "/q'");
  CHECK(quiet.exit_code == 0);
  CHECK(quiet.output.empty());
}

// SPDX-License-Identifier: MIT
// Large inputs: a 10^6-line data file is refused with the limit named (before it is split, so memory stays
// bounded: data/csv_reader.hpp), and a fit states its cost before it starts (selection/fit_cost.hpp).
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "selection/fit_cost.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <complex>
#include <filesystem>
#include <fstream>

using namespace admitgen;

namespace {

/// `rows` rows f,re,im of y = 0.2 + 0.3 (jf/500)/(1 + jf/500) (Re y > 0, |y| ~ 0.2-0.5: plausible) on a
/// linear grid from 100 Hz up in steps of `step` Hz.
void write_table(const std::string& path, long rows, double step) {
  std::ofstream out(path);
  out << "f,re,im\n";
  for (long i = 0; i < rows; ++i) {
    const double f = 100.0 + step * static_cast<double>(i);
    const std::complex<double> s(0.0, f / 500.0), y = 0.2 + 0.3 * s / (1.0 + s);
    out << fmt::format("{:.6f},{:.9f},{:.9f}\n", f, y.real(), y.imag());
  }
}

}  // namespace

TEST_CASE("large inputs: a 10^6-line data file is refused with the limit named, nothing written") {
  const std::string dir = test::scratch_dir("large_inputs_million");
  write_table(dir + "/million.csv", 1'000'000, 0.004);
  const auto r = test::run_admitgen(fmt::format("fit {}/million.csv --out {}/out --quiet", dir, dir));
  CHECK(r.exit_code == 2);
  CHECK_MESSAGE((r.output.find("more than 200000 lines") != std::string::npos ||
                 r.output.find("larger than 16 MiB") != std::string::npos), r.output);
  CHECK(r.output.find("million.csv") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/out"));
  // Just past the line limit, and just past the size limit (a long comment line), in-process.
  write_table(dir + "/lines.csv", kMaxDataFileLines, 0.01);  // + the header line
  CHECK_THROWS_WITH_AS(read_measurement(dir + "/lines.csv", {}), doctest::Contains("more than 200000 lines"), FileError);
  {
    std::ofstream out(dir + "/bytes.csv");
    out << "# " << std::string(kMaxDataFileBytes, 'x') << "\n100,0.1,0.1\n200,0.1,0.1\n300,0.1,0.1\n";
  }
  CHECK_THROWS_WITH_AS(read_measurement(dir + "/bytes.csv", {}), doctest::Contains("larger than 16 MiB"), FileError);
  // At the line limit the file is read.
  write_table(dir + "/at_limit.csv", kMaxDataFileLines - 1, 0.01);
  CHECK(read_measurement(dir + "/at_limit.csv", {}).size() == kMaxDataFileLines - 1);
}

TEST_CASE("large inputs: a fit of 10^5 points states its cost before it starts") {
  const std::string dir = test::scratch_dir("large_inputs_cost");
  write_table(dir + "/points.csv", 100'000, 0.039);  // 100 Hz - 4 kHz
  const auto r = test::run_admitgen(fmt::format("fit {}/points.csv --out {}/out --cost-only", dir, dir));
  CHECK_MESSAGE(r.exit_code == 0, r.output);
  CHECK_MESSAGE(r.output.find("cost estimate: 100000 points, 16 order(s)") != std::string::npos, r.output);
  CHECK(r.output.find("likelihood evaluations at") != std::string::npos);
  // Growth's budget is stated when the grid may grow, and not otherwise.
  CHECK(r.output.find("if the grid grows") != std::string::npos);
  const auto fixed = test::run_admitgen(fmt::format("fit {}/points.csv --out {}/out --cost-only --grid-growth 0", dir, dir));
  CHECK_MESSAGE(fixed.exit_code == 0, fixed.output);
  CHECK(fixed.output.find("if the grid grows") == std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/out"));  // --cost-only writes nothing
  // Every fit prints it first (a small one here: one order).
  const auto small = test::run_admitgen(fmt::format("fit '{}' --out {}/small --qmax 0 --smax 0 --live 20",
                                                    test::sample("reference/q1s1_sigma0.01.csv"), dir));
  CHECK(small.exit_code == 0);
  CHECK(small.output.find("cost estimate: 200 points, 1 order(s)") < small.output.find("selected"));
}

TEST_CASE("large inputs: the cost model matches the bundled fits within a factor 2") {
  // The bundled fits record their likelihood evaluations per order (models[].likelihood_calls); the estimate's
  // evaluation count over the same orders and live points must be within a factor 2 of their sum. (The
  // model's constant 27 was read off these fits, whose whole-fit ratios span 19-36: the test guards the
  // stated accuracy against a change of the sampler, not the constant's independence.) The bundled fits ran
  // the full sampler; the golden fit (tests/golden/expected) runs the pole sampler, whose constant is 15.
  for (const auto* name : {"fits/q1s1_reference.json", "fits/basotect_round_10cm_passive/fit.json",
                           "synthetic/mpp_three_layer_fit/fit.json", "synthetic/glass_beads_40mm_fit/fit.json",
                           "golden"}) {
    CAPTURE(name);
    std::ifstream in(std::string(name) == "golden" ? test::sample("../tests/golden/expected/fit.json") : test::sample(name));
    const auto fit = nlohmann::json::parse(in);
    FitSettings s;
    // The grid fitted: grown beyond the settings' when the fit grew it.
    const auto& grid = fit.contains("grid") ? fit["grid"] : fit["settings"];
    s.qmax = grid["qmax"].get<int>();
    s.smax = grid["smax"].get<int>();
    s.sampler.live = fit["settings"]["live"].get<int>();
    // The sampler the fit ran (fits of earlier versions without the key ran the full sampler).
    s.sampler_kind = fit["models"][0].value("sampler", std::string("full")) == "full" ? SamplerKind::full : SamplerKind::poles;
    double recorded = 0.0;
    int orders = 0;
    for (const auto& m : fit["models"]) {
      recorded += m["likelihood_calls"].get<double>() * s.sampler.live / m.value("live", s.sampler.live);
      ++orders;
    }
    Measurement data;
    data.f_hz = Eigen::ArrayXd::LinSpaced(50, 100.0, 4000.0);
    data.y = Eigen::ArrayXcd::Constant(50, std::complex<double>(0.3, 0.1));
    const auto e = estimate_fit_cost(data, s);
    CHECK(e.orders == orders);
    CHECK(e.evaluations / recorded > 0.5);
    CHECK(e.evaluations / recorded < 2.0);
  }
}

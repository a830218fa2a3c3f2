// SPDX-License-Identifier: MIT
// The posterior companion files of fit.json (io/posterior_export.hpp, docs/posterior_files.md):
// covariance against an independent one-pass computation, equal-weight draws against the weighted
// mean, and the files written by `admitgen fit`.
#include "data/csv_reader.hpp"
#include "inference/posterior.hpp"
#include "io/posterior_export.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

using namespace admitgen;
using namespace admitgen::test;

namespace {

/// Q0S1 on the reference data with 100 live points: a real posterior (5 parameters) in well under a second.
ModelResult small_run() {
  const Measurement data = read_measurement(sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
  FitSettings settings;
  settings.sampler.live = 100;
  settings.sampler.seed = 3;
  return fit_order(data, Order(0, 1), settings);
}

std::vector<std::vector<double>> read_csv_rows(const std::string& text, std::string& header) {
  std::istringstream in(text);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream fields(line);
    for (std::string f; std::getline(fields, f, ',');) row.push_back(std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("posterior export: covariance equals the one-pass weighted moments, its diagonal the summaries' std") {
  const ModelResult m = small_run();
  Eigen::VectorXd mean;
  const Eigen::MatrixXd cov = posterior_covariance(m.run, mean);
  const Eigen::ArrayXd w = posterior_weights(m.run);
  const int d = m.run.dim;
  REQUIRE(cov.rows() == d);
  for (int a = 0; a < d; ++a) {
    // Independent form: E[θ_a θ_b] − E[θ_a] E[θ_b] summed point by point. Its cancellation error is
    // about ε·E[θ_a²]/var_a ≤ 1e-16 · (|μ|/σ)² ≈ 1e-16 · 1e6 here, so 1e-8 relative is decisive.
    double ma = 0.0;
    for (std::size_t i = 0; i < m.run.size(); ++i) ma += w[static_cast<Eigen::Index>(i)] * m.run.point(i)[a];
    CHECK(mean[a] == doctest::Approx(ma).epsilon(1e-12));
    for (int b = 0; b < d; ++b) {
      double mb = 0.0, mab = 0.0;
      for (std::size_t i = 0; i < m.run.size(); ++i) {
        const double wi = w[static_cast<Eigen::Index>(i)];
        mb += wi * m.run.point(i)[b];
        mab += wi * m.run.point(i)[a] * m.run.point(i)[b];
      }
      const double scale = std::sqrt(cov(a, a) * cov(b, b));
      CHECK(std::abs(cov(a, b) - (mab - ma * mb)) <= 1e-8 * scale);
    }
    // summarize() computes each std by its own two-pass loop: agreement to rounding (1e-10 relative).
    CHECK(std::sqrt(cov(a, a)) == doctest::Approx(m.parameters[static_cast<std::size_t>(a)].std).epsilon(1e-10));
  }
  CHECK((cov - cov.transpose()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("posterior export: equal-weight draws are run points, round(ESS) of them, with the weighted mean") {
  const ModelResult m = small_run();
  const Eigen::MatrixXd s = equal_weight_samples(m.run, 11);
  const double ess = effective_sample_size(posterior_weights(m.run));
  CHECK(s.rows() == static_cast<Eigen::Index>(std::round(ess)));
  REQUIRE(s.rows() > 50);  // 100 live points give an ESS in the hundreds: a meaningful mean test
  std::set<std::vector<double>> points;
  for (std::size_t i = 0; i < m.run.size(); ++i) points.insert(std::vector<double>(m.run.point(i), m.run.point(i) + m.run.dim));
  for (Eigen::Index r = 0; r < s.rows(); ++r) {
    const Eigen::VectorXd row = s.row(r).transpose();
    CHECK(points.count(std::vector<double>(row.data(), row.data() + row.size())) == 1);
  }
  // Systematic resampling has at most the Monte-Carlo error of i.i.d. draws, σ/√N per parameter; with
  // the fixed seed, 4σ/√N (a 6e-5 two-sided chance per parameter for i.i.d. draws) cannot flake.
  for (int a = 0; a < m.run.dim; ++a) {
    const auto& p = m.parameters[static_cast<std::size_t>(a)];
    CHECK(std::abs(s.col(a).mean() - p.mean) <= 4.0 * p.std / std::sqrt(static_cast<double>(s.rows())));
  }
  CHECK(equal_weight_samples(m.run, 11) == s);  // deterministic for a seed
}

TEST_CASE("posterior export: fit writes posterior.json, one samples CSV per order and predictive.csv") {
  const std::string dir = scratch_dir("posterior_export");
  const std::string data = sample("reference/q1s1_sigma0.01.csv");
  for (const char* threads : {"1", "2"}) {
    const auto r = run_admitgen("fit '" + data + "' --qmax 1 --smax 1 --live 60 --seed 4 --quiet --threads " +
                                threads + " --out '" + dir + "/t" + threads + "'");
    REQUIRE(r.exit_code == 0);
  }
  const std::string out = dir + "/t1";
  const auto fit = nlohmann::json::parse(read_text(out + "/fit.json"));
  REQUIRE(fit["posterior"] == "posterior.json");
  const auto index = nlohmann::json::parse(read_text(out + "/posterior.json"));
  CHECK(index["schema"] == "admitgen.posterior/1");
  CHECK(index["selected"] == fit["selected"]["order"]);
  REQUIRE(index["orders"].size() == fit["models"].size());
  for (const auto& o : index["orders"]) {
    std::string header;
    const auto rows = read_csv_rows(read_text(out + "/" + o["samples_csv"].get<std::string>()), header);
    std::string names;
    for (const auto& n : o["parameters"]) names += (names.empty() ? "" : ",") + n.get<std::string>();
    CHECK(header == names);
    CHECK(rows.size() == o["draws"].get<std::size_t>());
    CHECK(o["covariance"].size() == o["parameters"].size());
    // The draws of every order also have the summaries' mean within 4σ/√N (see the test above).
    const auto& model = *std::find_if(fit["models"].begin(), fit["models"].end(),
                                      [&](const auto& m) { return m["order"] == o["order"]; });
    for (std::size_t a = 0; a < o["parameters"].size(); ++a) {
      double sum = 0.0;
      for (const auto& row : rows) sum += row[a];
      const double std = model["parameters"][a]["std"], mu = model["parameters"][a]["mean"];
      CHECK(std::abs(sum / static_cast<double>(rows.size()) - mu) <= 4.0 * std / std::sqrt(double(rows.size())));
      CHECK(std::sqrt(o["covariance"][a][a].get<double>()) == doctest::Approx(std).epsilon(1e-10));
    }
  }
  // predictive.csv holds exactly fit.json's predictive numbers (17 digits read back bit for bit).
  std::string header;
  const auto rows = read_csv_rows(read_text(out + "/predictive.csv"), header);
  CHECK(header.rfind("f_hz,re_G_data,im_G_data,alpha_data,re_G_median,re_G_lo95,re_G_hi95", 0) == 0);
  const auto& pred = fit["predictive"];
  REQUIRE(rows.size() == pred["f_hz"].size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    CHECK(rows[k][0] == pred["f_hz"][k].get<double>());
    CHECK(rows[k][4] == pred["re_G"][1][k].get<double>());
    CHECK(rows[k][5] == pred["re_G"][0][k].get<double>());
    CHECK(rows[k][6] == pred["re_G"][2][k].get<double>());
    CHECK(rows[k][11] == pred["alpha"][0][k].get<double>());
    CHECK(rows[k][5] <= rows[k][4]);
    CHECK(rows[k][4] <= rows[k][6]);
  }
  // Independent of the thread count, byte for byte.
  for (const char* name : {"posterior.json", "posterior_Q1S1.csv", "predictive.csv"})
    CHECK(read_text(out + "/" + name) == read_text(dir + "/t2/" + name));
}

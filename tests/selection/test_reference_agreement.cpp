// SPDX-License-Identifier: MIT
// Peer agreement with dynesty (rslice, 500 live points) on the
// reference file (samples/reference/README.md), and recovery of the true Q1S1 parameters.
#include "data/csv_reader.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <map>

using namespace admitgen;

TEST_SUITE("statistical") {
  TEST_CASE("reference file: ln Z agrees with dynesty - Q1S1 posterior covers the truth") {
    const Measurement data = read_measurement(test::sample("reference/q1s1_sigma0.01.csv"), ReadOptions{});
    // The seed paper's setup (--prior table1: Table 1's uniform box, run by the full sampler), K = 2N, 500 live
    // points, seed 1: as the peer runs.
    FitSettings settings;
    settings.priors = PriorRanges::table1();
    settings.priors_origin = "table1";
    settings.sampler.live = 500;
    struct Peer {
      double log_z, error;
      bool error_is_spread;
    };
    // dynesty rslice column of the README table; Q2S1 has only a seed-to-seed spread (3 seeds).
    const std::map<std::string, Peer> peers{{"Q0S1", {700.70, 0.40, false}},
                                            {"Q1S1", {1268.89, 0.48, false}},
                                            {"Q0S2", {1234.15, 0.53, false}},
                                            {"Q2S1", {1268.53, 0.50, true}}};
    for (const auto& [name, peer] : peers) {
      const ModelResult m = fit_order(data, Order::parse(name), settings);
      CHECK(m.sampler == "full");
      // Combined errors: 2√(e_ours² + e_peer²) (a 95 % band for two independent estimates); for Q2S1
      // the peer's seed-to-seed spread stands for its error.
      const double tol = 2.0 * std::hypot(m.run.log_z_error, peer.error);
      MESSAGE(name, ": admitgen ", m.run.log_z, " ± ", m.run.log_z_error, " (", m.run.calls, " calls), dynesty ",
              peer.log_z, std::string(peer.error_is_spread ? " spread " : " ± "), peer.error);
      CHECK(std::abs(m.run.log_z - peer.log_z) <= tol);
      if (name == "Q1S1") {
        // Truth from the file header (paper Table 2): within 3 posterior standard deviations.
        const std::map<std::string, double> truth{{"G_inf", 0.469}, {"A_1", -26062}, {"lambda_1", 55250},
                                                  {"B_1", 2019},    {"C_1", -263},   {"alpha_1", 1530},
                                                  {"beta_1", 10063}};
        for (const auto& p : m.parameters) {
          INFO(p.name, " mean ", p.mean, " std ", p.std, " truth ", truth.at(p.name));
          CHECK(std::abs(p.mean - truth.at(p.name)) <= 3.0 * p.std);
          CHECK(p.ci95_lo < p.mean);
          CHECK(p.mean < p.ci95_hi);
        }
      }
    }
  }
}

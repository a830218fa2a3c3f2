// SPDX-License-Identifier: MIT
// Real data: every real Basotect measurement (TU Berlin, samples/basotect_tuberlin)
// fits end to end over the Q0-3 × S0-3 grid, and the selected order explains the data.
//
// Settings: 100 live points (not 500), one missed-mode retry round and the grid as given, to keep the four 904-1025-point
// fits to about a minute each on two cores; the residual bound below holds with margin at this size.
#include "data/csv_reader.hpp"
#include "inference/likelihood.hpp"
#include "model/multipole.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace admitgen;

TEST_SUITE("statistical") {
  TEST_CASE("Basotect: every file fits end to end over Q0-3 x S0-3 and the selected order explains the data") {
    // Bounds on the selected order's max-likelihood model: relative RMS residual
    // √(Σ|y − G|² / Σ|y|²) and the RMS error of the absorption α = 1 − |R|² against the file's own α.
    // Without a pole pair the residual is 60 %, with one pair 20-44 %: the bounds separate a fit that
    // captured the material from one that did not. Measured (100 live, seed 1): round_10cm 1.9 % /
    // 0.005, round_5cm 4.1 % / 0.007, rect_5cm 5.5 % / 0.026, rect_10cm 17 % / 0.077. rect_10cm gets its
    // own, looser bound: its data carry a sharp, lightly damped quarter-wave resonance near 590 Hz and its
    // best Q ≤ 3, S ≤ 3 fits press against the Table 1 prior bounds (G∞ at −1, C at ±1000, α at 0), so the
    // default priors cannot express it (wider ranges only move it onto new bounds; see docs/validation.md).
    struct Case {
      const char* file;
      double max_relative_residual;
      double max_alpha_rms;
    };
    ReadOptions read;
    read.columns = ColumnMap::parse("f,_,_,_,_,re,im,_");
    ReadOptions read_alpha;  // the file's stored absorption column, read through the same parser
    read_alpha.columns = ColumnMap::parse("f,_,_,_,_,_,re,im");
    read_alpha.plausibility_errors = false;  // (Im y, alpha) is no admittance: its "Re y < 0" is expected
    for (const Case c : {Case{"round_10cm", 0.05, 0.02}, Case{"round_5cm", 0.08, 0.02}, Case{"rect_5cm", 0.08, 0.05},
                         Case{"rect_10cm", 0.25, 0.12}}) {
      const std::string path = test::sample(std::string("basotect_tuberlin/") + c.file + ".csv");
      const Measurement data = read_measurement(path, read);
      const Eigen::ArrayXd alpha_measured = read_measurement(path, read_alpha).y.imag();
      FitSettings settings;
      settings.sampler.live = 100;
      settings.missed_mode_retries = 1;
      settings.grid_growth = 0;  // this grid is the test's subject; growth is tested in test_grid_growth.cpp
      Progress quiet(false);
      const FitResult fit = run_fit(data, settings, quiet);
      REQUIRE(fit.models.size() == 16);
      const ModelResult& chosen = fit.models[fit.selected];
      const Likelihood like(data, chosen.order, DataCount::two_per_point);
      const std::size_t best = max_likelihood_index(chosen.run);
      const double residual = std::sqrt(like.sum_squared_residual(chosen.run.point(best)) / data.y.abs2().sum());
      const Eigen::VectorXd theta = Eigen::Map<const Eigen::VectorXd>(chosen.run.point(best), chosen.order.dim());
      const Eigen::ArrayXd alpha_model = absorption(evaluate_multipole(chosen.order, theta, data.omega()));
      const double alpha_rms = std::sqrt((alpha_model - alpha_measured).square().mean());
      MESSAGE(std::string(c.file), ": selected ", chosen.order.name(), ", ln Z ", chosen.run.log_z, " ± ", chosen.run.log_z_error,
              ", relative RMS residual ", residual, ", alpha RMS error ", alpha_rms, ", warnings left ",
              fit.warnings.size());
      CHECK(residual <= c.max_relative_residual);
      CHECK(alpha_rms <= c.max_alpha_rms);
      for (const auto& m : fit.models) {
        CHECK(std::isfinite(m.run.log_z));
        // Q0S0 has no pole: the pole sampler's evidence is the closed form itself.
        CHECK(m.run.stopped_by == (m.order.dim() == 1 && m.sampler != "full" ? "analytic" : "dlogz"));
      }
    }
  }
}

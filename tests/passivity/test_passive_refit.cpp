// SPDX-License-Identifier: MIT
// The discrete refit under Re H ≥ 0 up to Nyquist (codegen/discrete_model.hpp, docs/passivity.md), certified
// by the discrete Hamiltonian test (checks/passivity.hpp), and the emit pipeline built on it (emit/emit.hpp).
#include "checks/passivity.hpp"
#include "codegen/discrete_model.hpp"
#include "codegen/template_text.hpp"
#include "emit/emit.hpp"
#include "output/fit_reader.hpp"
#include "physics/multipole_surface.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace admitgen;
using codegen::DiscreteModel;

namespace {

std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> f;
  for (int i = 0; i < n; ++i) f.push_back(lo * std::pow(hi / lo, i / double(n - 1)));
  return f;
}

}  // namespace

TEST_CASE("passive refit: refits that go negative near Nyquist are constrained and certified") {
  // Committed fits (posterior means, passive) refitted by plain least squares at their data band leave
  // Re H < 0 near Nyquist at some rates, fold factors and FIR lengths; the constrained refit must certify
  // every one of them.
  int repaired = 0, cases = 0;
  for (const char* file : {"fits/q1s1_reference.json", "synthetic/glass_beads_40mm_fit/fit.json",
                           "synthetic/mpp_three_layer_fit/fit.json", "fits/basotect_round_10cm_passive/fit.json"}) {
    const auto fit = read_fit_file(test::sample(file));
    const auto surface = multipole_from_fit(fit, "", Estimate::mean, file);
    if (!continuous_passivity(surface.order, surface.theta.data()).passive) continue;
    const auto f = log_grid(fit["input"]["f_min_hz"].get<double>(), fit["input"]["f_max_hz"].get<double>(), 200);
    for (double fs : {16000.0, 24000.0, 44100.0, 48000.0}) {
      if (f.back() >= 0.45 * fs) continue;
      for (double fold : {4.0, 0.5, 0.25}) {
        for (int taps = 1; taps <= 8; taps += 1) {
          codegen::DiscretiseOptions plain;
          plain.fir_taps = taps;
          plain.fold_factor = fold;
          const DiscreteModel m0 = codegen::discretise(surface.order, surface.theta, fs, f, plain);
          ++cases;
          if (checks::discrete_passivity(m0).passive) continue;
          codegen::DiscretiseOptions constrained = plain;
          constrained.passivity_violations = emit::discrete_passivity_violations;  // what emit ships
          const DiscreteModel m1 = codegen::discretise(surface.order, surface.theta, fs, f, constrained);
          CAPTURE(file);
          CAPTURE(fs);
          CAPTURE(fold);
          CAPTURE(taps);
          CHECK(m1.passive_certified);
          CHECK(m1.passive_rounds >= 1);
          CHECK(checks::discrete_passivity(m1).passive);
          // The constraint binds where the plain refit was negative, mostly outside the data: the in-band
          // error may grow, but stays within 10x the unconstrained refit's or 1e-2, whichever is larger.
          CHECK(m1.refit_max_rel_error <= std::max(10.0 * m0.refit_max_rel_error, 1e-2));
          ++repaired;
        }
      }
    }
  }
  MESSAGE(repaired << " of " << cases << " plain refits were non-passive and were repaired");
  CHECK(repaired >= 10);  // the catalogue holds real cases
}

TEST_CASE("emit pipeline: every format and rate of the reference fit passes admitgen check") {
  const auto fit = read_fit_file(test::sample("fits/q1s1_reference.json"));
  const std::string tpl = codegen::load_template("", "admitgen_boundary.h.in");
  for (auto format : {codegen::Format::f32, codegen::Format::q31, codegen::Format::q15}) {
    codegen::EmitSettings s;
    s.fs_hz = {16000.0, 24000.0, 44100.0, 48000.0, 96000.0};
    s.format = format;
    s.name = "wall";
    const auto r = emit::emit(fit, "q1s1_reference.json", s, tpl, "wall.h");
    CAPTURE(codegen::format_name(format));
    CHECK(r.safe());
    CHECK(r.refusal("wall.h").empty());
    for (const auto& rate : r.emission.rates) CHECK(rate.model.passive_certified);
    // An older fit without a passive estimate: the posterior mean is emitted and the header says so.
    CHECK(r.header.find("no passive estimate") != std::string::npos);
  }
}

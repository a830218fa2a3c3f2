// SPDX-License-Identifier: MIT
// Reference densities of the combined search (diagnosis/reference_prior.hpp, docs/method.md "Reference
// priors in the combined search"):
//  * q is a density on [0, 1] and its inverse CDF inverts ∫₀ᵘ q: both checked against a composite
//    Simpson integral of q (4000 panels, error far below the 1e-7 tolerance for the widths used, whose
//    narrowest normal spans 40 panels per standard deviation);
//  * a joint candidate sampled from a reference density (L/q over q) has the evidence of the same
//    candidate sampled from its prior: agreement within 3 combined reported errors at 200 live points,
//    for a reference centred on the posterior and for one centred 3 posterior widths off it (the
//    uniform share then carries the run); the reference run needs fewer likelihood calls.
#include "diagnosis/effect_identification.hpp"
#include "diagnosis/reference_prior.hpp"
#include "validation_cases.hpp"

#include <doctest/doctest.h>

#include <cmath>

namespace admitgen::test {
namespace {

/// ∫_a^b q(u) du by composite Simpson with n (even) panels.
double integral(const diagnosis::ReferenceDensity& q, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = std::exp(q.log_density(a)) + std::exp(q.log_density(b));
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * std::exp(q.log_density(a + i * h));
  return sum * h / 3.0;
}

}  // namespace

TEST_CASE("reference density: normalised on [0, 1], its inverse CDF inverts its integral") {
  for (const auto& q : {diagnosis::ReferenceDensity(0.3, 0.01, 0.1), diagnosis::ReferenceDensity(0.98, 0.05, 0.5),
                        diagnosis::ReferenceDensity(0.0, 0.2, 0.1)}) {
    CHECK(std::abs(integral(q, 0.0, 1.0, 4000) - 1.0) < 1e-7);
    for (const double v : {0.01, 0.2, 0.5, 0.77, 0.999}) {
      const double u = q.inverse_cdf(v);
      CAPTURE(v);
      CHECK(std::abs(integral(q, 0.0, u, 4000) - v) < 1e-7);
      // Against bisection on Q to 2⁻⁵²: Q is evaluated to a few ulp (≤ 1e-15) and Q' = q ≥ ε ≥ 0.1, so the
      // two roots differ by at most 1e-15/0.1 plus Newton's stopping step 1e-15: 2e-14 bounds both.
      double lo = 0.0, hi = 1.0;
      for (int i = 0; i < 52; ++i) (q.cdf(0.5 * (lo + hi)) < v ? lo : hi) = 0.5 * (lo + hi);
      CHECK(std::abs(u - 0.5 * (lo + hi)) < 2e-14);
    }
  }
  CHECK(diagnosis::ReferenceDensity().uniform());
  CHECK(diagnosis::ReferenceDensity().inverse_cdf(0.25) == 0.25);
}

TEST_CASE("diagnose: a joint candidate sampled from a reference density has the evidence sampled from its prior") {
  // The real data carry a spacing error and an edge gap; the joint candidate edge_gap + mic_spacing has
  // three parameters.
  ValidationCase c;
  c.truth = "mic_spacing";
  c.effect = "mic_spacing:delta_m=1mm";
  c.second = "edge_gap:width_m=0.5mm,depth_m=30mm";
  c.material = base_materials()[1];
  c.seed = 4;
  const auto request = case_request(c, 60);
  const Eigen::ArrayXd& f = request.real.f_hz;
  const auto candidates = diagnosis::effect_candidates(f, request.sim.admittance(f), request.sim, request.tube);
  const auto find = [&](const std::string& name) {
    for (const auto& e : candidates)
      if (e.name == name) return &e;
    FAIL("no candidate ", name);
    return &candidates.front();
  };
  const diagnosis::EffectLikelihood likelihood(request.real.y);
  diagnosis::EffectCandidate joint = diagnosis::combine_effects({find("edge_gap"), find("mic_spacing")});
  NestedSettings s;
  s.live = 200;
  s.dlogz = 0.01;
  s.seed = 21;
  const NestedRun prior = run_nested_sampling(diagnosis::effect_model(joint, likelihood), s);
  const auto posterior = summarize(prior, diagnosis::effect_model(joint, likelihood).parameter_names);
  for (const double offset : {0.0, 3.0}) {
    auto shifted = posterior;
    for (std::size_t k = 0; k < shifted.size(); ++k) {
      const double u_lo = joint.priors[k].cdf(shifted[k].ci95_lo), u_hi = joint.priors[k].cdf(shifted[k].ci95_hi);
      const double du = offset * (u_hi - u_lo);
      shifted[k].ci95_lo = joint.priors[k].transform(std::clamp(u_lo + du, 0.0, 1.0));
      shifted[k].ci95_hi = joint.priors[k].transform(std::clamp(u_hi + du, 0.0, 1.0));
    }
    joint.reference = diagnosis::reference_densities(joint.priors, shifted, diagnosis::kReferenceShareJoint);
    s.seed = 22;
    const NestedRun reference = run_nested_sampling(diagnosis::effect_model(joint, likelihood), s);
    CAPTURE(offset);
    INFO("prior: ", prior.log_z, " ± ", prior.log_z_error, " (", prior.calls, " calls); reference: ", reference.log_z,
         " ± ", reference.log_z_error, " (", reference.calls, " calls)");
    CHECK(std::abs(reference.log_z - prior.log_z) <=
          3.0 * std::hypot(reference.log_z_error, prior.log_z_error));
    if (offset == 0.0) CHECK(reference.calls < prior.calls);
  }
}

}  // namespace admitgen::test

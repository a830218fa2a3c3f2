// SPDX-License-Identifier: MIT
// How `diagnose` computes the evidence of its candidates (diagnosis/effect_identification.hpp):
//  * the 1-parameter quadrature agrees with nested sampling of the same candidate within 3 of the
//    sampler's reported errors (the quadrature's own error, ~1e-6 nats, is negligible next to it);
//  * the whole diagnosis is byte-identical with 1 and 2 threads;
//  * screening in the combined search picks what running every joint candidate in full picks, and every
//    candidate it left screened, run in full, is below the pick;
//  * early stop: every candidate that stopped early, re-run to the end, has a best likelihood below the
//    bound that stopped it and an evidence more than the early-stop margin below the leader, and the
//    verdict, its evidence and the ranking of the candidates that ran to the end are unchanged.
#include "diagnosis/diagnosis_record.hpp"
#include "io/diagnosis_file.hpp"
#include "diagnosis/effect_identification.hpp"
#include "inference/evidence.hpp"
#include "validation_cases.hpp"

#include <doctest/doctest.h>

#include <limits>

namespace admitgen::test {
namespace {

/// A clear case of the validation suite (porous base, reference tube, σ = 0.003, 120 points).
ValidationCase clear_case(const std::string& truth, const std::string& effect, std::uint64_t seed) {
  ValidationCase c;
  c.truth = truth;
  c.effect = effect;
  c.material = base_materials()[0];
  c.seed = seed;
  c.label = effect;
  return c;
}

}  // namespace

TEST_CASE("diagnose: quadrature evidence of 1-parameter effects agrees with nested sampling") {
  const auto request = case_request(clear_case("reference_plane", "reference_plane:delta_m=0.5mm", 7), 60);
  const Eigen::ArrayXd& f = request.real.f_hz;
  const Eigen::ArrayXcd y_sim = request.sim.admittance(f);
  const auto candidates = diagnosis::effect_candidates(f, y_sim, request.sim, request.tube);
  const diagnosis::EffectLikelihood likelihood(request.real.y);
  int compared = 0;
  for (const auto& c : candidates) {
    if (c.priors.size() != 1) continue;
    const Model model = diagnosis::effect_model(c, likelihood);
    const NestedRun quadrature = evidence_by_quadrature(model);
    NestedSettings s;
    s.live = 400;
    s.dlogz = 0.01;
    s.seed = 11;
    const NestedRun sampled = run_nested_sampling(model, s);
    INFO(c.name, ": quadrature ", quadrature.log_z, " ± ", quadrature.log_z_error, " (", quadrature.calls,
         " calls), nested sampling ", sampled.log_z, " ± ", sampled.log_z_error, " (", sampled.calls, " calls)");
    CHECK(quadrature.log_z_error < 1e-5);
    CHECK(std::abs(quadrature.log_z - sampled.log_z) <= 3.0 * sampled.log_z_error);
    // The best likelihood the quadrature found is at least the sampler's (it refines the maximum).
    CHECK(quadrature.max_log_likelihood >= sampled.max_log_likelihood - 1e-6);
    ++compared;
  }
  CHECK(compared >= 4);  // reference_plane, mic_spacing, temperature, heteroscedastic_noise, frequency_scale
}

TEST_CASE("diagnose: diagnosis.json is byte-identical with 1 and 2 threads") {
  auto request = case_request(clear_case("frame_resonance", "frame_resonance:f0_hz=600,q=8,y_peak=0.1", 3), 40);
  request.settings.threads = 1;
  const std::string one = io::diagnosis_text(diagnosis::diagnosis_record(diagnosis::run_diagnosis(request)));
  request.settings.threads = 2;
  const std::string two = io::diagnosis_text(diagnosis::diagnosis_record(diagnosis::run_diagnosis(request)));
  CHECK(one == two);
}

namespace {

/// A reference-plane shift with tube losses (29 mm tube, x1 = 0.3 m), 40 live points: two effects, so the
/// combined search runs a second round over joint candidates.
diagnosis::DiagnosisRequest two_effect_request() {
  auto c = clear_case("reference_plane", "reference_plane:delta_m=3mm", 11);
  c.second = "tube_losses";
  c.tube_diameter_m = 0.029;
  c.mic_distance_m = 0.3;
  return case_request(c, 40);
}

}  // namespace

TEST_CASE("diagnose: a combined search gives a byte-identical diagnosis.json with 1 and 2 threads") {
  // Two effects: the second round samples several joint candidates on their own seed streams.
  auto request = two_effect_request();
  request.settings.threads = 1;
  const auto d = diagnosis::run_diagnosis(request);
  REQUIRE(d.verdict.explanation.size() >= 2);
  const std::string one = io::diagnosis_text(diagnosis::diagnosis_record(d));
  request.settings.threads = 2;
  CHECK(one == io::diagnosis_text(diagnosis::diagnosis_record(diagnosis::run_diagnosis(request))));
}

TEST_CASE("diagnose: screening the combined search's joint candidates picks what full runs pick") {
  // Two effects (the case above): the second round screens every remaining effect jointly with the first
  // and runs in full only those within 20 dB of the best or of decisive. Reference: the same search with
  // every joint candidate run in full (screen_live = live). Screening at 15 live points (a third of 40).
  auto request = two_effect_request();
  request.settings.screen_live = 15;
  const auto screened = diagnosis::run_diagnosis(request);
  request.settings.screen_live = request.settings.sampler.live;
  const auto full = diagnosis::run_diagnosis(request);
  REQUIRE(screened.verdict.explanation.size() >= 2);
  REQUIRE(screened.verdict.explanation.size() == full.verdict.explanation.size());
  for (std::size_t k = 0; k < full.verdict.explanation.size(); ++k)
    CHECK(screened.verdict.explanation[k].effect == full.verdict.explanation[k].effect);
  CHECK(screened.verdict.effect == full.verdict.effect);
  REQUIRE(screened.explanation.rounds.size() == full.explanation.rounds.size());
  int left = 0;
  for (std::size_t r = 0; r < full.explanation.rounds.size(); ++r) {
    const auto& s = screened.explanation.rounds[r];
    const auto& f = full.explanation.rounds[r];
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& e : f) best = std::max(best, e.log_z);
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i].method != "screened") continue;
      ++left;
      CAPTURE(s[i].name);
      CHECK(f[i].log_z < best);  // could not have been picked
    }
  }
  MESSAGE(left, " joint candidates left screened");
  CHECK(left >= 1);
}

TEST_CASE("diagnose: early stop leaves the verdict alone and only stops candidates far below the leader") {
  // reference_plane (a quadrature candidate) leads, so sampled candidates that cannot come near it stop.
  auto request = case_request(clear_case("reference_plane", "reference_plane:delta_m=3mm", 5), 60);
  const auto with = diagnosis::run_diagnosis(request);
  request.settings.early_stop_deciban = 0.0;
  const auto without = diagnosis::run_diagnosis(request);
  CHECK(with.verdict.effect == "reference_plane");
  CHECK(with.verdict.effect == without.verdict.effect);
  CHECK(with.verdict.bayes_factor_deciban == without.verdict.bayes_factor_deciban);
  double leader = with.identification.log_z_none;
  for (const auto& e : with.identification.effects)
    if (e.method != "nested_sampling") leader = std::max(leader, e.log_z);
  int stopped = 0;
  for (const auto& e : with.identification.effects) {
    const auto full = std::find_if(without.identification.effects.begin(), without.identification.effects.end(),
                                   [&](const auto& x) { return x.candidate == e.candidate; });
    REQUIRE(full != without.identification.effects.end());
    CAPTURE(e.name);
    if (!e.stopped_early) {
      CHECK(e.log_z == full->log_z);  // same seed stream, same run
      continue;
    }
    ++stopped;
    CHECK(e.calls < full->calls);
    CHECK(full->max_log_likelihood <= e.log_z_bound);
    CHECK(deciban(full->log_z, leader) < -diagnosis::kEarlyStopDeciban);
  }
  MESSAGE(stopped, " of ", with.identification.effects.size(), " candidates stopped early");
  CHECK(stopped >= 1);
}

}  // namespace admitgen::test

// SPDX-License-Identifier: MIT
// What the fit says at the accuracy target (selection/accuracy_stop.hpp): the note of a met target and the warning
// of a missed one, on hand-made orders whose accuracy and evidence are set here.
#include "model/multipole.hpp"
#include "selection/accuracy_stop.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace admitgen;

namespace {

ModelResult model(const Order& order, double log_z, const OrderAccuracy& accuracy) {
  ModelResult m{order, {}, 0, 0.0, {}};
  m.run.log_z = log_z;
  m.accuracy = accuracy;
  return m;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("accuracy stop: a missed target names noise, a spike or a feature, a met one gives no warning") {
  const FitSettings settings;
  Measurement data;  // a passive Q0S1 wall; only the passivity case below reads it
  data.f_hz = Eigen::ArrayXd::LinSpaced(100, 300.0, 3000.0);
  data.y = evaluate_multipole(Order(0, 1), (Eigen::VectorXd(5) << 0.3, 0.2, 0.05, 2000.0, 6000.0).finished(),
                              data.omega());
  const passivity::LazyPassiveBound bound(data);
  OrderAccuracy a;
  a.max_band_delta_alpha = 0.05;
  a.max_band_delta_alpha_beside_peak = 0.05;
  a.worst_band_hz = 1000.0;
  a.peak_hz = 990.0;
  a.residual_lag1 = 0.1;  // uncorrelated: noise
  std::vector<ModelResult> models{model(Order(0, 1), 0.0, a)};
  CHECK(has(target_missed_warning(data, settings, models, 0, bound), "is noise"));
  CHECK(has(target_out_of_reach(data, settings, models[0], bound), "is noise"));
  models[0].accuracy->residual_lag1 = 0.99;
  models[0].accuracy->peak_points = 1;  // one point: a spike, and beside it the order misses too
  CHECK(has(target_missed_warning(data, settings, models, 0, bound), "spike at 990 Hz 1 point(s) wide"));
  CHECK(has(target_missed_warning(data, settings, models, 0, bound), "beside it |Δα| reaches 0.050"));
  CHECK(target_out_of_reach(data, settings, models[0], bound).empty());  // more poles may help beside the spike
  models[0].accuracy->max_band_delta_alpha_beside_peak = 0.004;  // the spike alone misses: out of reach
  CHECK(has(target_out_of_reach(data, settings, models[0], bound), "beside it Q0S1 meets the target"));
  models[0].accuracy->max_band_delta_alpha_beside_peak = 0.05;
  models[0].accuracy->peak_points = 20;
  models[0].accuracy->peak_width_hz = 120.0;
  CHECK(has(target_missed_warning(data, settings, models, 0, bound), "feature at 990 Hz about 120 Hz wide"));
  CHECK(target_out_of_reach(data, settings, models[0], bound).empty());
  // An order over the budget that meets the target does not silence the warning; within it, it does.
  OrderAccuracy met;
  met.meets = true;
  models.push_back(model(Order(0, 3), 10.0, met));  // 6 buffers
  FitSettings budget = settings;
  budget.max_buffers = 4;
  CHECK_FALSE(target_missed_warning(data, budget, models, 0, bound).empty());
  CHECK(target_missed_warning(data, settings, models, 0, bound).empty());
}

TEST_CASE("accuracy stop: passivity puts the target out of reach only when no passive admittance meets it") {
  // The passive estimate costs 10× the best sample's residual (beyond PassiveEstimate::kCostRatio = 1.25). On a
  // passive Q0S1 wall the passive bound (the closest passive admittance of any order) meets the target: more poles
  // might, so growth goes on. On the same wall with Re y negated (Re y < 0 over the band, which no passive
  // admittance follows: its best has Re G = 0 there, α off by far more than 0.01) the bound misses it: out of reach.
  Measurement data;
  data.f_hz = Eigen::ArrayXd::LinSpaced(200, 300.0, 3000.0);
  data.y = evaluate_multipole(Order(0, 1), (Eigen::VectorXd(5) << 0.3, 0.2, 0.05, 2000.0, 6000.0).finished(),
                              data.omega());
  OrderAccuracy a;
  a.max_band_delta_alpha = a.max_band_delta_alpha_beside_peak = 0.05;
  a.residual_lag1 = 0.99;
  a.peak_points = 20;
  ModelResult m = model(Order(0, 1), 0.0, a);
  m.passive.relative_rms_residual = 0.1;
  m.passive.best_sample_relative_rms_residual = 0.01;
  const FitSettings settings;
  {
    const passivity::LazyPassiveBound bound(data);
    CHECK(target_out_of_reach(data, settings, m, bound).empty());
  }
  Measurement active = data;
  active.y.real() = -data.y.real();
  const passivity::LazyPassiveBound bound(active);
  const std::string why = target_out_of_reach(active, settings, m, bound);
  CHECK(has(why, "passivity, not the order, limits what ships"));
  CHECK(has(why, "the passive bound) misses the target too"));
  // Passivity costing little (within kCostRatio) is not the limit, whatever the bound.
  m.passive.relative_rms_residual = 0.012;
  CHECK(target_out_of_reach(active, settings, m, bound).empty());
}

TEST_CASE("accuracy stop: the note of a met target says what the best-evidence order would change") {
  // Q0S1 meets the target; Q0S2 has 3 nats more evidence, and its second pair has zero residues, so it is the same
  // curve: α would change by exactly 0.
  Measurement data;
  data.f_hz = Eigen::ArrayXd::LinSpaced(100, 300.0, 3000.0);
  const Eigen::VectorXd small = (Eigen::VectorXd(5) << 0.3, 0.2, 0.05, 2000.0, 6000.0).finished();
  Eigen::VectorXd big(9);
  big << 0.3, 0.2, 0.05, 2000.0, 6000.0, 0.0, 0.0, 3000.0, 12000.0;
  data.y = evaluate_multipole(Order(0, 1), small, data.omega());
  OrderAccuracy met;
  met.meets = true;
  std::vector<ModelResult> models{model(Order(0, 1), 100.0, met), model(Order(0, 2), 103.0, met)};
  models[0].passive.theta = small;
  models[1].passive.theta = big;
  const FitSettings settings;
  const std::string note = target_met_note(data, settings, models, 0, false);
  CHECK(has(note, "+3.0 nats at Q0S2"));
  CHECK(has(note, "Q0S1 already meets |Δα| ≤ 0.01 in every band"));
  CHECK(has(note, "2 more buffers per node would change α by at most 0.000"));
  // The selection has the best evidence: a note only when growth would have continued.
  models[1].run.log_z = 90.0;
  CHECK(target_met_note(data, settings, models, 0, false).empty());
  CHECK(has(target_met_note(data, settings, models, 0, true), "not fitted"));
  // A selection that misses the target gets no note, unless growth stopped because the target is out of reach
  // while the evidence would have grown.
  models[0].accuracy->meets = false;
  CHECK(target_met_note(data, settings, models, 0, false).empty());
  CHECK(has(target_met_note(data, settings, models, 0, true), "more poles cannot meet the target"));
}

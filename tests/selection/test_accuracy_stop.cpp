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
  OrderAccuracy a;
  a.max_band_delta_alpha = 0.05;
  a.worst_band_hz = 1000.0;
  a.peak_hz = 990.0;
  a.residual_lag1 = 0.1;  // uncorrelated: noise
  std::vector<ModelResult> models{model(Order(0, 1), 0.0, a)};
  CHECK(has(target_missed_warning(settings, models, 0), "is noise"));
  models[0].accuracy->residual_lag1 = 0.99;
  models[0].accuracy->peak_points = 1;  // one point: a spike
  CHECK(has(target_missed_warning(settings, models, 0), "spike at 990 Hz 1 point(s) wide"));
  models[0].accuracy->peak_points = 20;
  models[0].accuracy->peak_width_hz = 120.0;
  CHECK(has(target_missed_warning(settings, models, 0), "feature at 990 Hz about 120 Hz wide"));
  // An order over the budget that meets the target does not silence the warning; within it, it does.
  OrderAccuracy met;
  met.meets = true;
  models.push_back(model(Order(0, 3), 10.0, met));  // 6 buffers
  FitSettings budget = settings;
  budget.max_buffers = 4;
  CHECK_FALSE(target_missed_warning(budget, models, 0).empty());
  CHECK(target_missed_warning(settings, models, 0).empty());
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
  // A selection that misses the target gets no note.
  models[0].accuracy->meets = false;
  CHECK(target_met_note(data, settings, models, 0, true).empty());
}

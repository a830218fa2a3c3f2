// SPDX-License-Identifier: MIT
// The pole sampler and the full sampler on a real measurement (Basotect round 10 cm, the README's quick
// start) against an independent evidence: importance sampling over the poles (pole_importance.hpp), its
// proposal built from the posterior samples of both samplers, so that a mode either of them found is
// covered. docs/method.md, "Status of the pole sampler", records the figures.
#include "data/csv_reader.hpp"
#include "pole_importance.hpp"
#include "selection/fit.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <string>

using namespace admitgen;

namespace {

Measurement quick_start_file() {
  ReadOptions read;
  read.columns = ColumnMap::parse("f,_,_,_,_,re,im,_");
  return read_measurement(test::sample("basotect_tuberlin/round_10cm.csv"), read);
}

struct Comparison {
  ModelResult poles, full;
  test::ImportanceEstimate reference;
};

Comparison compare(const Measurement& data, const Order& order, int live, std::uint64_t seed) {
  FitSettings settings;
  settings.sampler.live = live;
  settings.sampler.seed = seed;
  settings.sampler_kind = SamplerKind::poles;
  Comparison c{fit_order(data, order, settings), {Order(0, 0), {}, 0, 0.0, {}}, {}};
  settings.sampler.seed = seed + 1000;
  const ModelResult other = fit_order(data, order, settings);
  settings.sampler_kind = SamplerKind::full;
  settings.sampler.seed = seed;
  if (std::getenv("FULL")) c.full = fit_order(data, order, settings);
  std::vector<const ModelResult*> runs{&c.poles, &other};
  if (std::getenv("FULL")) runs.push_back(&c.full);
  c.reference = test::importance_log_z(data, order, PriorRanges::table1(), runs, 200, 20000, 2000, 17);
  MESSAGE("second pole run (seed ", seed + 1000, "): ", other.run.log_z, " ± ", other.run.log_z_error);
  MESSAGE(order.name(), " (", live, " live, seed ", seed, "): pole sampler ", c.poles.run.log_z, " ± ",
          c.poles.run.log_z_error, " (", c.poles.sampler, ", box correction ", c.poles.truncation_correction, " ± ",
          c.poles.truncation_correction_error, ", ESS ratio ", c.poles.reweighted_ess_ratio, ", ", c.poles.run.calls,
          " calls, ", c.poles.seconds, " s), full sampler ", c.full.run.log_z, " ± ", c.full.run.log_z_error, " (",
          c.full.run.calls, " calls, ", c.full.seconds, " s), importance sampling ", c.reference.log_z, " ± ",
          c.reference.error, " (ESS ", c.reference.ess, " of 20000)");
  return c;
}

}  // namespace

TEST_SUITE("statistical") {
  TEST_CASE("Basotect measure (dev)") {
    const Measurement data = quick_start_file();
    const char* env = std::getenv("ORDERS");
    std::string orders = env ? env : "Q1S3";
    const int live = std::getenv("LIVE") ? std::atoi(std::getenv("LIVE")) : 100;
    std::size_t pos = 0;
    while (pos < orders.size()) {
      const std::size_t end = orders.find(',', pos);
      const std::string name = orders.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
      compare(data, Order::parse(name), live, 1);
      if (end == std::string::npos) break;
      pos = end + 1;
    }
  }
}

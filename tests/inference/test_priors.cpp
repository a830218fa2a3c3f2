// The prior transform: ranges, ordering in the reduced space, and the order-statistics density.
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "inference/priors.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace admitgen;

TEST_CASE("prior transform: reduced samples are ordered, inside the ranges, and beta >= 0") {
  const Order o(3, 3);
  const PriorRanges pr = PriorRanges::table1();
  const PriorTransform t(o, pr, true);
  Rng rng(3);
  std::vector<double> u(static_cast<std::size_t>(o.dim())), th(u.size());
  for (int n = 0; n < 2000; ++n) {
    for (auto& x : u) x = rng.uniform();
    t(u.data(), th.data());
    for (int q = 0; q < o.q(); ++q) {
      REQUIRE(th[static_cast<std::size_t>(Order::lambda(q))] >= pr.lambda.lo);
      REQUIRE(th[static_cast<std::size_t>(Order::lambda(q))] <= pr.lambda.hi);
      if (q > 0) REQUIRE(th[static_cast<std::size_t>(Order::lambda(q))] >= th[static_cast<std::size_t>(Order::lambda(q - 1))]);
    }
    for (int s = 0; s < o.s(); ++s) {
      REQUIRE(th[static_cast<std::size_t>(o.beta(s))] >= 0.0);
      REQUIRE(th[static_cast<std::size_t>(o.beta(s))] <= pr.beta.hi);
      if (s > 0) REQUIRE(th[static_cast<std::size_t>(o.alpha(s))] >= th[static_cast<std::size_t>(o.alpha(s - 1))]);
    }
  }
}

TEST_CASE("prior transform: the order-statistics map has the right marginals") {
  // For n = 3 sorted U(0,1), E[x_(k)] = k/(n+1). With 40000 draws the standard error of each mean is
  // below sqrt(1/12/40000) = 0.0015, so a tolerance of 0.006 is 4 standard errors.
  PriorRanges pr;
  pr.lambda = {0.0, 1.0};
  const Order o(3, 0);
  const PriorTransform t(o, pr, true);
  Rng rng(9);
  std::vector<double> u(static_cast<std::size_t>(o.dim())), th(u.size());
  double sums[3] = {0, 0, 0};
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    for (auto& x : u) x = rng.uniform();
    t(u.data(), th.data());
    for (int q = 0; q < 3; ++q) sums[q] += th[static_cast<std::size_t>(Order::lambda(q))];
  }
  for (int q = 0; q < 3; ++q) CHECK(std::abs(sums[q] / n - (q + 1) / 4.0) < 0.006);
}

TEST_CASE("prior file: overrides, validation and symmetric-range requirement") {
  const std::string dir = test::scratch_dir("priors");
  test::write_text(dir + "/ok.json", R"({"lambda": [0, 200000], "G_inf": [-2, 2]})");
  const PriorRanges pr = PriorRanges::from_file(dir + "/ok.json");
  CHECK(pr.lambda.hi == 200000.0);
  CHECK(pr.g_inf.lo == -2.0);
  CHECK(pr.a.hi == 40000.0);  // untouched families keep Table 1
  test::write_text(dir + "/bad_key.json", R"({"lambdas": [0, 1]})");
  test::write_text(dir + "/bad_range.json", R"({"alpha": [5, 1]})");
  test::write_text(dir + "/acausal.json", R"({"alpha": [-5, 100]})");
  test::write_text(dir + "/not_json.json", "lambda = 3");
  for (const char* f : {"bad_key.json", "bad_range.json", "acausal.json", "not_json.json", "missing.json"})
    CHECK_THROWS_AS(PriorRanges::from_file(dir + "/" + f), InputError);
  PriorRanges asym;
  asym.beta = {0.0, 15000.0};
  CHECK_THROWS_AS(PriorTransform(Order(0, 1), asym, true), InputError);
  CHECK_NOTHROW(PriorTransform(Order(0, 1), asym, false));
}

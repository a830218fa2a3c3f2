// SPDX-License-Identifier: MIT
// The prior transform: ranges, ordering in the reduced space, and the order-statistics density.
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "io/priors_file.hpp"
#include "model/multipole.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace admitgen;

TEST_CASE("prior transform: folding gives the canonical copy with the same likelihood") {
  // Canonical: λ ascending, α ascending, β ≥ 0; re-sorted by β, θ(fold(u)) equals the θ-space fold of
  // θ(u) (the per-coordinate map is affine and β, C ranges are symmetric: 1 − u ↦ −θ up to one
  // rounding, so 1e-9 relative to the range width), and the model value is unchanged.
  const Order o(3, 3);
  const PriorRanges pr = PriorRanges::table1();
  const PriorTransform t(o, pr, true);
  Rng rng(3);
  std::vector<double> u(static_cast<std::size_t>(o.dim())), th(u.size()), th_folded(u.size());
  const Eigen::ArrayXd omega = Eigen::ArrayXd::LinSpaced(40, 600.0, 25000.0);
  for (int n = 0; n < 2000; ++n) {
    for (auto& x : u) x = rng.uniform();
    t(u.data(), th.data());
    t.fold(u.data());
    t(u.data(), th_folded.data());
    for (int q = 1; q < o.q(); ++q)
      REQUIRE(th_folded[static_cast<std::size_t>(Order::lambda(q))] >= th_folded[static_cast<std::size_t>(Order::lambda(q - 1))]);
    for (int s = 0; s < o.s(); ++s) {
      REQUIRE(th_folded[static_cast<std::size_t>(o.beta(s))] >= 0.0);
      if (s > 0) REQUIRE(th_folded[static_cast<std::size_t>(o.alpha(s))] >= th_folded[static_cast<std::size_t>(o.alpha(s - 1))]);
    }
    std::vector<double> expected = th, reported = th_folded;
    fold_to_reduced(o, expected.data());
    fold_to_reduced(o, reported.data());
    for (std::size_t k = 0; k < th.size(); ++k) REQUIRE(std::abs(reported[k] - expected[k]) <= 1e-9 * 4e4);
    const Eigen::Map<const Eigen::VectorXd> a(th.data(), o.dim()), b(th_folded.data(), o.dim());
    const Eigen::ArrayXcd ga = evaluate_multipole(o, a, omega), gb = evaluate_multipole(o, b, omega);
    REQUIRE((ga - gb).abs().maxCoeff() <= 1e-9 * (1.0 + ga.abs().maxCoeff()));
    std::vector<double> again = u;
    t.fold(again.data());
    REQUIRE(again == u);  // idempotent
  }
}

TEST_CASE("prior file: overrides, validation and symmetric-range requirement") {
  const std::string dir = test::scratch_dir("priors");
  test::write_text(dir + "/ok.json", R"({"lambda": [0, 200000], "G_inf": [-2, 2]})");
  const PriorRanges pr = io::read_priors_file(dir + "/ok.json");
  CHECK(pr.lambda.hi == 200000.0);
  CHECK(pr.g_inf.lo == -2.0);
  CHECK(pr.a.hi == 40000.0);  // untouched families keep Table 1
  test::write_text(dir + "/bad_key.json", R"({"lambdas": [0, 1]})");
  test::write_text(dir + "/bad_range.json", R"({"alpha": [5, 1]})");
  test::write_text(dir + "/acausal.json", R"({"alpha": [-5, 100]})");
  test::write_text(dir + "/not_json.json", "lambda = 3");
  for (const char* f : {"bad_key.json", "bad_range.json", "acausal.json", "not_json.json", "missing.json"})
    CHECK_THROWS_AS(io::read_priors_file(dir + "/" + f), InputError);
  PriorRanges asym;
  asym.beta = {0.0, 15000.0};
  CHECK_THROWS_AS(PriorTransform(Order(0, 1), asym, true), InputError);
  CHECK_NOTHROW(PriorTransform(Order(0, 1), asym, false));
}

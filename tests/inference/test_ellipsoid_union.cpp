// SPDX-License-Identifier: MIT
// Draws from the union of bounding ellipsoids (inference/ellipsoid_union.hpp) and the nested sampler's
// constrained step that uses them (NestedSettings::ellipsoid_draws), against closed forms.
#include "core/rng.hpp"
#include "inference/ellipsoid_union.hpp"
#include "inference/nested_sampler.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Cholesky>

#include <cmath>
#include <vector>

using namespace admitgen;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Points equally spaced on two circles of radius r: the sample covariance of each is (r²/2)·n/(n − 1)·I
/// and every point sits at the same whitened distance, so each bounding ellipsoid (enlargement 1) is the
/// circle itself.
struct TwoCircles {
  Eigen::MatrixXd u;
  LivePointClusters clusters;
};

TwoCircles two_circles(double x0, double x1, double y, double r, int per_circle) {
  TwoCircles c{Eigen::MatrixXd(2, 2 * per_circle), {}};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < per_circle; ++i) {
      const double phi = 2.0 * kPi * i / per_circle;
      c.u.col(k * per_circle + i) << (k == 0 ? x0 : x1) + r * std::cos(phi), y + r * std::sin(phi);
      c.clusters.label.push_back(k);
    }
  for (int k = 0; k < 2; ++k) c.clusters.axes.push_back(covariance_axes(c.u.middleCols(k * per_circle, per_circle)));
  return c;
}

}  // namespace

TEST_CASE("ellipsoid union: draws are uniform on two overlapping circles (lens share, acceptance, volume)") {
  // Circles of radius r = 0.15 with centres d = 0.2 apart. Lens area 2r²acos(d/2r) − (d/2)√(4r² − d²)
  // (the symmetric circle-circle intersection), union area 2πr² − lens. Uniform draws on the union fall in
  // the lens with probability lens/union = 0.2118; the multiplicity test keeps a draw with probability
  // union/(2πr²). With 200 000 draws the binomial standard errors are ≤ 0.0011; tolerance 5 of them.
  const double r = 0.15, d = 0.2;
  const TwoCircles c = two_circles(0.4, 0.4 + d, 0.5, r, 64);
  const EllipsoidUnion bounds(c.u, c.clusters, 1.0);
  CHECK(bounds.size() == 2);
  CHECK(bounds.log_volume() == doctest::Approx(std::log(2.0 * r * r)).epsilon(1e-9));
  const double lens = 2.0 * r * r * std::acos(d / (2.0 * r)) - 0.5 * d * std::sqrt(4.0 * r * r - d * d);
  const double uni = 2.0 * kPi * r * r - lens;
  Rng rng(5);
  Eigen::VectorXd x(2);
  long kept = 0, in_lens = 0, left_only = 0, outside = 0;
  constexpr long kDraws = 200000;
  for (long i = 0; i < kDraws; ++i) {
    int cluster = -1;
    if (!bounds.draw(rng, x, cluster)) continue;
    ++kept;
    const bool a = (x - Eigen::Vector2d(0.4, 0.5)).norm() <= r * (1.0 + 1e-12);
    const bool b = (x - Eigen::Vector2d(0.4 + d, 0.5)).norm() <= r * (1.0 + 1e-12);
    CHECK(bounds.contains(static_cast<std::size_t>(cluster), x));
    in_lens += a && b;
    left_only += a && !b;
    outside += !a && !b;
  }
  const auto close = [](double p_hat, double p, double n) { return std::abs(p_hat - p) <= 5.0 * std::sqrt(p * (1 - p) / n); };
  const double n = static_cast<double>(kept);
  CHECK(outside == 0);
  CHECK(close(static_cast<double>(kept) / kDraws, uni / (2.0 * kPi * r * r), kDraws));
  CHECK(close(static_cast<double>(in_lens) / n, lens / uni, n));
  CHECK(close(static_cast<double>(left_only) / n, (kPi * r * r - lens) / uni, n));
}

TEST_SUITE("statistical") {
  TEST_CASE("nested sampling with ellipsoid draws: ln Z of a correlated Gaussian equals the closed form") {
    // L(u) = N(u; μ, Σ) on the unit cube in 4-D, μ = (0.5, 0.4, 0.6, 0.5), Σ = s²(I + 0.9·(J − I)) (unit
    // diagonal, correlation 0.9 between every pair: a thin ellipsoid along the diagonal, like the pole
    // posteriors), s = 0.03: the cube holds it to 1e-20, so Z = ∫ L du = 1, ln Z = 0. 16 seeds at 200 live
    // points: the mean of 16 estimates must lie within 3 standard errors (spread/√16) of 0, and the spread
    // within a factor 2 of the mean reported error (relative standard error of a 16-value spread ≈ 18 %),
    // as for the slice step (test_sampler_statistics.cpp); the draws must need under a third of the slice
    // step's calls (measured: about a tenth).
    constexpr int kDim = 4;
    constexpr double s = 0.03, rho = 0.9;
    Eigen::MatrixXd cov = Eigen::MatrixXd::Constant(kDim, kDim, rho * s * s);
    cov.diagonal().setConstant(s * s);
    const Eigen::LLT<Eigen::MatrixXd> llt(cov);
    const Eigen::MatrixXd chol = llt.matrixL();
    const Eigen::Vector4d mu(0.5, 0.4, 0.6, 0.5);
    const double log_norm = -0.5 * kDim * std::log(2.0 * kPi) - chol.diagonal().array().log().sum();
    const Model model{{"a", "b", "c", "d"}, [](const double* u, double* th) { std::copy(u, u + kDim, th); },
                      [&](const double* th) {
                        const Eigen::Vector4d x = Eigen::Map<const Eigen::Vector4d>(th) - mu;
                        return log_norm - 0.5 * chol.triangularView<Eigen::Lower>().solve(x).squaredNorm();
                      }};
    std::vector<double> log_z, err;
    long calls_ellipsoids = 0, calls_slices = 0;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) {
      NestedSettings settings;
      settings.live = 200;
      settings.seed = seed;
      settings.ellipsoid_draws = true;
      const NestedRun run = run_nested_sampling(model, settings);
      log_z.push_back(run.log_z);
      err.push_back(run.log_z_error);
      calls_ellipsoids += run.calls;
      settings.ellipsoid_draws = false;
      if (seed == 1) calls_slices = run_nested_sampling(model, settings).calls;
    }
    const auto [mean, spread, reported] = test::seed_scatter(log_z, err);
    MESSAGE("16 seeds: mean ln Z ", mean, ", spread ", spread, ", mean reported error ", reported, "; calls per run ",
            calls_ellipsoids / 16, " against ", calls_slices, " with slices");
    CHECK(std::abs(mean) <= 3.0 * spread / 4.0);
    CHECK(spread <= 2.0 * reported);
    CHECK(spread >= 0.5 * reported);
    CHECK(calls_ellipsoids / 16 < calls_slices / 3);
  }
}

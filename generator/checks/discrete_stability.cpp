// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace admitgen::checks {
namespace {

using u64 = std::uint64_t;

/// Real term z = 1 − ε, ε = M 2^−k: |z| < 1 ⇔ 0 < M < 2^(k+1) (exact).
bool real_inside(std::int64_t m, int k) { return m > 0 && (k + 1 >= 62 || m < (std::int64_t{1} << (k + 1))); }

/// Pair z = (1 + a 2^−k) + j b 2^−k: |z|² < 1 ⇔ a (2^(k+1) + a) + b² < 0 ⇔ (a = −m < 0)
/// m² + b² < m 2^(k+1) ⇔ ⌊(m² + b²)/m⌋ < 2^(k+1), decided in unsigned 64-bit integers without overflow
/// (|a|, |b| < 2^31, so m² + b² < 2^63).
bool pair_inside(std::int64_t a, std::int64_t b, int k) {
  if (a >= 0) return false;
  const u64 m = static_cast<u64>(-a), bb = static_cast<u64>(b < 0 ? -b : b);
  if (k + 1 >= 63) return true;
  return (m * m + bb * bb) / m < (u64{1} << (k + 1));
}

/// 1 − |z| without cancellation, from t = |z|² − 1.
double margin_from(double t) { return -t / (1.0 + std::sqrt(1.0 + t)); }

}  // namespace

CheckResult check_discrete_stability(const CheckSubject& s) {
  CheckResult r;
  r.name = "discrete_stability";
  if (!s.header)
    return r.not_applicable("a fit has no emitted coefficients (check the header made by admitgen emit)");
  const bool fixed = s.header->format != codegen::Format::f32;
  r.method = fixed ? "|z| < 1 of the quantised coefficients, decided exactly in integer arithmetic"
                   : "|z| < 1 of the emitted float coefficients (exact in double)";
  double worst = std::numeric_limits<double>::infinity();
  std::string worst_where;
  DiscreteStabilityDetails d;
  for (const auto& rate : s.header->rates) {
    const auto& m = rate.model;
    double rate_margin = std::numeric_limits<double>::infinity();
    auto visit = [&](bool pair, std::size_t i, bool inside, double margin) {
      const std::string where = term_location(rate.fs_hz, m, pair, i);
      if (!inside)
        r.fail(fmt::format("{}: |z| = {:.12f} is {} the unit circle (margin {:.3g})", where, 1.0 - margin,
                           margin == 0.0 ? "on" : "on or outside", margin));
      rate_margin = std::min(rate_margin, margin);
      if (margin < worst) worst = margin, worst_where = where;
    };
    for (std::size_t i = 0; i < m.real.size(); ++i) {
      const double eps = m.real[i].eps;
      const bool inside = fixed ? real_inside(rate.fixed->real[i].eps, rate.fixed->bits + rate.fixed->real[i].shift)
                                : codegen::inside_unit_circle(m.real[i]);
      visit(false, i, inside, 1.0 - std::abs(1.0 - eps));
    }
    for (std::size_t i = 0; i < m.pair.size(); ++i) {
      const auto& p = m.pair[i];
      const bool inside = fixed ? pair_inside(rate.fixed->pair[i].e_r, rate.fixed->pair[i].p_i,
                                              rate.fixed->bits + rate.fixed->pair[i].shift)
                                : codegen::inside_unit_circle(p);
      visit(true, i, inside, margin_from(p.e_r * (2.0 + p.e_r) + p.p_i * p.p_i));
    }
    StabilityRate figures;
    figures.fs_hz = rate.fs_hz;
    if (std::isfinite(rate_margin)) {
      figures.min_margin = rate_margin;  // 1 − max |z|
      figures.slowest_time_constant_s = rate_margin > 0.0 ? 1.0 / (rate_margin * rate.fs_hz) : -1.0;
    }
    d.rates.push_back(figures);
  }
  r.details = d;
  r.summary = std::isfinite(worst) ? fmt::format("min margin 1 - |z| = {:.4g} at {}", worst, worst_where)
                                   : "FIR only: every pole at z = 0";
  return r;
}

}  // namespace admitgen::checks

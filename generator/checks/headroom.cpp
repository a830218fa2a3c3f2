// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <limits>

namespace admitgen::checks {

/// docs/physics.md §3.3: for |u| ≤ 1, |state| ≤ ‖h_state‖₁ (tight for the worst-case sign input), so each
/// state needs ‖h_state‖₁ ≤ 1 (Q1.31 range [−1, 1)) and the output needs ‖h‖₁ ≤ 2^out_shift; the 64-bit
/// sums need Σ|mantissa| < 2^B per state update and over the output table (coefficients.hpp).
CheckResult check_headroom(const CheckSubject& s) {
  CheckResult r;
  r.name = "headroom";
  if (!s.header || s.header->format == codegen::Format::f32)
    return r.not_applicable(s.header ? "f32: floating point (no Q-format range)" : "a fit has no emitted coefficients");
  r.method = "L1 norm of each state's and the output's impulse response against its Q range (full-scale input, "
             "any sign pattern); 64-bit accumulator bounds";
  double worst_state = 0.0, worst_out = 0.0;
  HeadroomDetails d;
  for (const auto& rate : s.header->rates) {
    const auto& q = *rate.fixed;
    const auto& m = rate.model;
    const double full = std::ldexp(1.0, q.bits);
    double state_max = 0.0;
    for (std::size_t i = 0; i < m.real.size(); ++i) {
      // Σ ε|1 − ε|ⁿ = ε/(1 − |1 − ε|) for a stable pole; unbounded otherwise.
      const double eps = m.real[i].eps;
      const double l1 = codegen::inside_unit_circle(m.real[i]) ? eps / (1.0 - std::abs(1.0 - eps))
                                                               : std::numeric_limits<double>::infinity();
      state_max = std::max(state_max, l1);
      if (!(l1 <= 1.0)) r.fail(fmt::format("{}: state x L1 norm {:.9g} > 1: a full-scale input saturates it",
                                           term_location(rate.fs_hz, m, false, i), l1));
      if (std::abs(double(q.real[i].eps)) >= full)
        r.fail(fmt::format("{}: |eps mantissa| {} >= 2^{}: the 64-bit update can overflow",
                           term_location(rate.fs_hz, m, false, i), q.real[i].eps, q.bits));
    }
    for (std::size_t i = 0; i < m.pair.size(); ++i) {
      const auto [xi, eta] = codegen::state_l1(m.pair[i]);
      state_max = std::max({state_max, xi, eta});
      if (!(std::max(xi, eta) <= 1.0))
        r.fail(fmt::format("{}: state L1 norms xi {:.9g}, eta {:.9g} exceed 1: a full-scale input saturates them",
                           term_location(rate.fs_hz, m, true, i), xi, eta));
      const auto& t = q.pair[i];
      const double sum = std::abs(double(t.e_r)) + std::abs(double(t.p_i)) + std::abs(double(t.g));
      if (sum >= full)
        r.fail(fmt::format("{}: |e_r| + |p_i| + |g| mantissas = {:.0f} >= 2^{}: the 64-bit update can overflow",
                           term_location(rate.fs_hz, m, true, i), sum, q.bits));
    }
    double table = 0.0;
    for (auto v : q.fir) table += std::abs(double(v));
    for (const auto& t : q.real) table += std::abs(double(t.c));
    for (const auto& t : q.pair) table += std::abs(double(t.c_r)) + std::abs(double(t.c_i));
    if (table >= full)
      r.fail(fmt::format("fs {} Hz: output table sum of |mantissa| = {:.0f} >= 2^{}: the 64-bit accumulator can "
                         "overflow", rate.fs_hz, table, q.bits));
    if (q.acc_shift < 1 || q.acc_shift > 62)
      r.fail(fmt::format("fs {} Hz: acc_shift {} outside 1..62", rate.fs_hz, q.acc_shift));
    const double out_l1 = m.l1_norm(), range = std::ldexp(1.0, q.out_shift);
    if (!(out_l1 <= range))
      r.fail(fmt::format("fs {} Hz: output L1 norm {:.6g} > 2^out_shift = {:g}: a full-scale worst-case input "
                         "saturates the output (out_shift {} is too small)", rate.fs_hz, out_l1, range, q.out_shift));
    worst_state = std::max(worst_state, state_max);
    worst_out = std::max(worst_out, out_l1 / range);
    d.rates.push_back({rate.fs_hz, state_max, out_l1, range, table});
  }
  r.details = d;
  r.summary = fmt::format("max state L1 {:.6g} (range 1), max output L1 / 2^out_shift = {:.4g}", worst_state, worst_out);
  return r;
}

}  // namespace admitgen::checks

// SPDX-License-Identifier: MIT
/// @file
/// An independent integer model of the fixed-point recursion, written from docs/runtime.md ("Q formats and
/// rounding") and admitgen_rt.h, sharing no code with the runtime: the oracle the runtime's kernels (which
/// the generator runs for its golden vectors and limit-cycle checks) must match bit for bit. One node,
/// plain per-sample loop, FIR history as a shift register.
#pragma once

#include "codegen/coefficients.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace admitgen::test {

/// Q1.31 states of one node (x per real pole, ξ and η per pair, hist[k] = u^{n−k}, k < n_fir).
struct OracleState {
  std::vector<std::int32_t> x, xi, eta, hist;
};

namespace oracle_detail {
using i64 = std::int64_t;
/// floor(v / 2^s), s in [1, 62].
inline i64 floor_shr(i64 v, int s) { return v >= 0 ? (v >> s) : ~((~v) >> s); }
/// old + prod/2^s rounded toward zero of the result (magnitude truncation), saturated to int32.
inline std::int32_t add_tz(std::int32_t old, i64 prod, int s) {
  i64 v = i64(old) + floor_shr(prod, s);
  const std::uint64_t mask = (std::uint64_t{1} << s) - 1;
  if (v < 0 && (static_cast<std::uint64_t>(prod) & mask) != 0) v += 1;
  return static_cast<std::int32_t>(std::clamp<i64>(v, INT32_MIN, INT32_MAX));
}
}  // namespace oracle_detail

/// Zero state shaped for `c`.
inline OracleState oracle_zero_state(const codegen::FixedCoefficients& c) {
  return {std::vector<std::int32_t>(c.real.size(), 0), std::vector<std::int32_t>(c.pair.size(), 0),
          std::vector<std::int32_t>(c.pair.size(), 0), std::vector<std::int32_t>(c.fir.size(), 0)};
}

/// Output for `in` (Q1.31 values for q31, Q1.15 values for q15, held in int32) from state `st`, which
/// receives the final state.
inline std::vector<std::int32_t> oracle_fixed(const codegen::FixedCoefficients& c, const std::vector<std::int32_t>& in,
                                              OracleState& st) {
  using oracle_detail::add_tz;
  using oracle_detail::floor_shr;
  using oracle_detail::i64;
  const int b = c.bits;
  const bool q15 = c.format == codegen::Format::q15;
  std::vector<std::int32_t> y(in.size());
  const i64 round = i64{1} << (c.acc_shift - 1);
  const i64 lo = q15 ? INT16_MIN : INT32_MIN, hi = q15 ? INT16_MAX : INT32_MAX;
  for (std::size_t n = 0; n < in.size(); ++n) {
    const std::int32_t u = q15 ? in[n] * 65536 : in[n];
    for (std::size_t k = st.hist.size(); k-- > 1;) st.hist[k] = st.hist[k - 1];
    if (!st.hist.empty()) st.hist[0] = u;
    i64 acc = 0;
    for (std::size_t k = 0; k < st.hist.size(); ++k) acc += i64(c.fir[k]) * st.hist[k];
    for (std::size_t q = 0; q < c.real.size(); ++q) {
      const auto& t = c.real[q];
      st.x[q] = add_tz(st.x[q], i64(t.eps) * (i64(u) - st.x[q]), b + t.shift);
      acc += i64(t.c) * st.x[q];
    }
    for (std::size_t s = 0; s < c.pair.size(); ++s) {
      const auto& t = c.pair[s];
      const std::int32_t a = st.xi[s], e = st.eta[s];
      st.xi[s] = add_tz(a, i64(t.e_r) * a - i64(t.p_i) * e + i64(t.g) * u, b + t.shift);
      st.eta[s] = add_tz(e, i64(t.e_r) * e + i64(t.p_i) * a, b + t.shift);
      acc += i64(t.c_r) * st.xi[s] + i64(t.c_i) * st.eta[s];
    }
    y[n] = static_cast<std::int32_t>(std::clamp<i64>(floor_shr(acc + round, c.acc_shift), lo, hi));
  }
  return y;
}

}  // namespace admitgen::test

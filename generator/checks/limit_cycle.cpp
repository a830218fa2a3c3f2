// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"

#include "codegen/runtime_filter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace admitgen::checks {
namespace {

/// Simulation cap (zero-input samples); slower filters are checked against their proven envelope.
constexpr long kMaxSamples = 1L << 23;

/// Contraction factor |z| per term (real terms first, then pairs), in the term order.
std::vector<double> radii(const codegen::DiscreteModel& m) {
  std::vector<double> r;
  for (const auto& t : m.real) r.push_back(std::abs(1.0 - t.eps));
  for (const auto& p : m.pair) r.push_back(std::hypot(1.0 + p.e_r, p.p_i));
  return r;
}

/// |state| of every term (real poles first, then pairs as |ψ| = hypot(ξ, η)), in the term order.
template <typename Sample>
std::vector<double> state_magnitudes(codegen::RuntimeNode<Sample>& node) {
  std::vector<double> v;
  for (std::size_t q = 0; q < node.n_real(); ++q) v.push_back(std::abs(double(node.x(q))));
  for (std::size_t s = 0; s < node.n_pair(); ++s) v.push_back(std::hypot(double(node.xi(s)), double(node.eta(s))));
  return v;
}

/// Fixed point, on the runtime's own kernel (Sample int32_t: q31, int16_t: q15): from full-scale states
/// (and again after a full-scale worst-case-sign burst), zero input must drive every state to exactly 0
/// within FixedCoefficients::zero_decay_bound() samples; by the magnitude-truncation argument
/// (docs/runtime.md, "Q formats and rounding") it then stays 0. Beyond the simulation cap the states must
/// lie inside the proven envelope |s_n| ≤ rⁿ |s_0| + 1 LSB.
template <typename Sample>
void fixed_zero_input(CheckResult& r, int fs, const codegen::DiscreteModel& m, const codegen::FixedCoefficients& q,
                      LimitCycleRate& figures) {
  const long bound = q.zero_decay_bound();
  const long n = std::min(bound, kMaxSamples);
  const auto rad = radii(m);
  const std::int32_t diag = 1518500249;  // ⌊2^31/√2⌋: |ψ| just below full scale
  for (int scenario = 0; scenario < 2; ++scenario) {
    codegen::RuntimeNode<Sample> node(q, fs);
    if (scenario == 0) {
      for (std::size_t k = 0; k < node.n_real(); ++k) node.x(k) = INT32_MAX;
      for (std::size_t k = 0; k < node.n_pair(); ++k) node.xi(k) = diag, node.eta(k) = -diag;
    } else {
      const auto h = m.impulse_response(4096);
      const Sample full = std::numeric_limits<Sample>::max();
      std::vector<Sample> burst(h.size());
      for (std::size_t k = 0; k < h.size(); ++k) burst[k] = h[h.size() - 1 - k] >= 0.0 ? full : static_cast<Sample>(-full);
      node.process(burst);
    }
    const auto start = state_magnitudes(node);
    const auto out = node.process(std::vector<Sample>(static_cast<std::size_t>(n), 0));
    const auto now = state_magnitudes(node);
    const char* from = scenario == 0 ? "full-scale states" : "a full-scale worst-case burst";
    for (std::size_t i = 0; i < rad.size(); ++i) {
      const bool pair = i >= node.n_real();
      const std::size_t k = pair ? i - node.n_real() : i;
      const double allowed = n == bound ? 0.0 : start[i] * std::pow(rad[i], double(n)) + 1.5;
      if (now[i] > allowed)
        r.fail(fmt::format("{}: after {} zero-input samples from {} the state is still {:.0f} LSB (allowed {:.0f}): "
                           "limit cycle / deadband", term_location(fs, m, pair, k), n, from, now[i], allowed));
    }
    // zero_decay_bound() = (samples for every state to reach 0) + n_fir + 1, so the last n_fir + 1 outputs
    // must be exactly 0 (a longer window would include samples before a fast state has decayed).
    const long window = std::min<long>(n, static_cast<long>(q.fir.size()) + 1);
    if (n == bound && std::any_of(out.end() - window, out.end(), [](Sample v) { return v != 0; }))
      r.fail(fmt::format("fs {} Hz: output not exactly 0 after {} zero-input samples from {}", fs, n, from));
  }
  figures.zero_decay_bound = bound;
  figures.simulated_samples = n;
}

/// f32, on the runtime's own kernel. Round-to-nearest leaves x unchanged when ε|x| < ulp(x)/2, i.e.
/// ε ≲ 2^-24: the state then never decays (a deadband at any amplitude). From state 1 (|ψ| = 1), zero
/// input for twice the samples the exact envelope needs to fall by 2^-24 (capped): every state must be
/// below max(2 rⁿ, 2^-24).
void float_zero_input(CheckResult& r, int fs, const codegen::DiscreteModel& m, LimitCycleRate& figures) {
  const auto rad = radii(m);
  double slowest = 0.0;
  for (double v : rad) slowest = std::max(slowest, v);
  const double need = slowest < 1.0 ? 24.0 * std::log(2.0) / -std::log(slowest) : double(kMaxSamples);
  const long n = static_cast<long>(std::min(2.0 * std::ceil(need) + 1.0, double(kMaxSamples)));
  // The header's f32 tables are exactly representable: to_float gives back the emitted floats.
  codegen::RuntimeNodeF32 node(codegen::to_float(m), fs);
  for (std::size_t k = 0; k < node.n_real(); ++k) node.x(k) = 1.0f;
  for (std::size_t k = 0; k < node.n_pair(); ++k) node.xi(k) = 0.70710677f, node.eta(k) = 0.70710677f;
  node.run_zero_input(n);
  const auto now = state_magnitudes(node);
  for (std::size_t i = 0; i < rad.size(); ++i) {
    const bool pair = i >= node.n_real();
    const std::size_t k = pair ? i - node.n_real() : i;
    // Decayed as the exact envelope rⁿ (start 1) within a factor 2, or below 2^-24; when the capped run
    // cannot reach 2^-24, at least half the exact decay 1 − rⁿ must have happened (a stuck state shows none).
    const double exact = std::pow(rad[i], double(n));
    const bool decayed = now[i] <= std::max(2.0 * exact, std::ldexp(1.0, -24)) && 1.0 - now[i] >= 0.5 * (1.0 - exact);
    if (!decayed)
      r.fail(fmt::format("{}: zero-input state still {:.3g} of full scale after {} samples (exact decay {:.3g}): "
                         "float rounding deadband (the per-sample decrement is below half an ulp)",
                         term_location(fs, m, pair, k), now[i], n, exact));
  }
  figures.simulated_samples = n;
}

}  // namespace

CheckResult check_limit_cycles(const CheckSubject& s) {
  CheckResult r;
  r.name = "limit_cycle";
  if (!s.header) return r.not_applicable("a fit has no emitted coefficients");
  const bool fixed = s.header->format != codegen::Format::f32;
  r.method = fixed ? "zero input from full-scale states, bit-exact integer model of the runtime: every state must "
                     "reach exactly 0 (magnitude truncation)"
                   : "zero input from unit states, IEEE single simulation of the runtime: states must decay "
                     "below 2^-24 (no rounding deadband)";
  LimitCycleDetails d;
  long total = 0;
  for (const auto& rate : s.header->rates) {
    LimitCycleRate figures;
    figures.fs_hz = rate.fs_hz;
    const auto rad = radii(rate.model);
    if (std::any_of(rad.begin(), rad.end(), [](double v) { return !(v < 1.0); }))
      r.fail(fmt::format("fs {} Hz: a pole on or outside the unit circle (see discrete_stability): zero input does "
                         "not decay", rate.fs_hz));
    else if (s.header->format == codegen::Format::q31)
      fixed_zero_input<std::int32_t>(r, rate.fs_hz, rate.model, *rate.fixed, figures);
    else if (s.header->format == codegen::Format::q15)
      fixed_zero_input<std::int16_t>(r, rate.fs_hz, rate.model, *rate.fixed, figures);
    else
      float_zero_input(r, rate.fs_hz, rate.model, figures);
    total += figures.simulated_samples.value_or(0L);
    d.rates.push_back(figures);
  }
  r.details = d;
  r.summary = r.failures.empty() ? fmt::format("zero input decays to 0 at every rate ({} samples simulated)", total)
                                 : "zero input does not decay";
  return r;
}

}  // namespace admitgen::checks

// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"

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

/// Fixed point: from full-scale states (and again after a full-scale worst-case-sign burst), zero input
/// must drive every state to exactly 0 within FixedCoefficients::zero_decay_bound() samples; by the
/// magnitude-truncation argument (runtime/src/admitgen_rt_internal.h) it then stays 0. Beyond the
/// simulation cap the states must lie inside the proven envelope |s_n| ≤ rⁿ |s_0| + 1 LSB.
void fixed_zero_input(CheckResult& r, int fs, const codegen::DiscreteModel& m, const codegen::FixedCoefficients& q,
                      nlohmann::ordered_json& j) {
  const long bound = q.zero_decay_bound();
  const long n = std::min(bound, kMaxSamples);
  const auto rad = radii(m);
  const std::int32_t diag = 1518500249;  // ⌊2^31/√2⌋: |ψ| just below full scale
  for (int scenario = 0; scenario < 2; ++scenario) {
    codegen::FixedState st{std::vector<std::int32_t>(q.real.size(), INT32_MAX), std::vector<std::int32_t>(q.pair.size(), diag),
                           std::vector<std::int32_t>(q.pair.size(), -diag), std::vector<std::int32_t>(q.fir.size(), 0)};
    if (scenario == 1) {
      std::fill(st.x.begin(), st.x.end(), 0);
      std::fill(st.xi.begin(), st.xi.end(), 0);
      std::fill(st.eta.begin(), st.eta.end(), 0);
      const auto h = m.impulse_response(4096);
      const std::int32_t full = q.format == codegen::Format::q31 ? INT32_MAX : INT16_MAX;
      std::vector<std::int32_t> burst(h.size());
      for (std::size_t k = 0; k < h.size(); ++k) burst[k] = h[h.size() - 1 - k] >= 0.0 ? full : -full;
      codegen::run_fixed(q, burst, &st);
    }
    std::vector<double> start;
    for (auto v : st.x) start.push_back(std::abs(double(v)));
    for (std::size_t i = 0; i < st.xi.size(); ++i) start.push_back(std::hypot(double(st.xi[i]), double(st.eta[i])));
    const auto out = codegen::run_fixed(q, std::vector<std::int32_t>(static_cast<std::size_t>(n), 0), &st);
    const char* from = scenario == 0 ? "full-scale states" : "a full-scale worst-case burst";
    for (std::size_t i = 0; i < rad.size(); ++i) {
      const bool pair = i >= st.x.size();
      const std::size_t k = pair ? i - st.x.size() : i;
      const double now = pair ? std::hypot(double(st.xi[k]), double(st.eta[k])) : std::abs(double(st.x[k]));
      const double allowed = n == bound ? 0.0 : start[i] * std::pow(rad[i], double(n)) + 1.5;
      if (now > allowed)
        r.fail(fmt::format("{}: after {} zero-input samples from {} the state is still {:.0f} LSB (allowed {:.0f}): "
                           "limit cycle / deadband", term_location(fs, m, pair, k), n, from, now, allowed));
    }
    // zero_decay_bound() = (samples for every state to reach 0) + n_fir + 1, so the last n_fir + 1 outputs
    // must be exactly 0 (a longer window would include samples before a fast state has decayed).
    const long window = std::min<long>(n, static_cast<long>(q.fir.size()) + 1);
    if (n == bound && std::any_of(out.end() - window, out.end(), [](std::int32_t v) { return v != 0; }))
      r.fail(fmt::format("fs {} Hz: output not exactly 0 after {} zero-input samples from {}", fs, n, from));
  }
  j["zero_decay_bound"] = bound;
  j["simulated_samples"] = n;
}

/// f32: IEEE single simulation of the runtime's update expressions (runtime/src/admitgen_rt_process_f32.c).
/// Round-to-nearest leaves x unchanged when ε|x| < ulp(x)/2, i.e. ε ≲ 2^-24: the state then never decays
/// (a deadband at any amplitude). From state 1 (|ψ| = 1), zero input for twice the samples the exact
/// envelope needs to fall by 2^-24 (capped): every state must be below max(2 rⁿ, 2^-24).
void float_zero_input(CheckResult& r, int fs, const codegen::DiscreteModel& m, nlohmann::ordered_json& j) {
  const auto rad = radii(m);
  double slowest = 0.0;
  for (double v : rad) slowest = std::max(slowest, v);
  const double need = slowest < 1.0 ? 24.0 * std::log(2.0) / -std::log(slowest) : double(kMaxSamples);
  const long n = static_cast<long>(std::min(2.0 * std::ceil(need) + 1.0, double(kMaxSamples)));
  std::vector<float> x(m.real.size(), 1.0f), xi(m.pair.size(), 0.70710677f), eta(m.pair.size(), 0.70710677f);
  std::vector<float> eps, er, pi;
  for (const auto& t : m.real) eps.push_back(static_cast<float>(t.eps));
  for (const auto& p : m.pair) er.push_back(static_cast<float>(p.e_r)), pi.push_back(static_cast<float>(p.p_i));
  const float u = 0.0f;
  for (long k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = x[i] + eps[i] * (u - x[i]);
    for (std::size_t i = 0; i < xi.size(); ++i) {
      const float a = xi[i], b = eta[i];
      xi[i] = a + (er[i] * a - pi[i] * b);
      eta[i] = b + (er[i] * b + pi[i] * a);
    }
  }
  for (std::size_t i = 0; i < rad.size(); ++i) {
    const bool pair = i >= x.size();
    const std::size_t k = pair ? i - x.size() : i;
    const double now = pair ? std::hypot(double(xi[k]), double(eta[k])) : std::abs(double(x[k]));
    // Decayed as the exact envelope rⁿ (start 1) within a factor 2, or below 2^-24; when the capped run
    // cannot reach 2^-24, at least half the exact decay 1 − rⁿ must have happened (a stuck state shows none).
    const double exact = std::pow(rad[i], double(n));
    const bool decayed = now <= std::max(2.0 * exact, std::ldexp(1.0, -24)) && 1.0 - now >= 0.5 * (1.0 - exact);
    if (!decayed)
      r.fail(fmt::format("{}: zero-input state still {:.3g} of full scale after {} samples (exact decay {:.3g}): "
                         "float rounding deadband (the per-sample decrement is below half an ulp)",
                         term_location(fs, m, pair, k), now, n, exact));
  }
  j["simulated_samples"] = n;
}

}  // namespace

CheckResult check_limit_cycles(const CheckSubject& s) {
  CheckResult r;
  r.name = "limit_cycle";
  if (!s.header) {
    r.status = Status::not_applicable;
    r.summary = "a fit has no emitted coefficients";
    return r;
  }
  const bool fixed = s.header->format != codegen::Format::f32;
  r.method = fixed ? "zero input from full-scale states, bit-exact integer model of the runtime: every state must "
                     "reach exactly 0 (magnitude truncation)"
                   : "zero input from unit states, IEEE single simulation of the runtime: states must decay "
                     "below 2^-24 (no rounding deadband)";
  nlohmann::ordered_json rates = nlohmann::ordered_json::array();
  long total = 0;
  for (const auto& rate : s.header->rates) {
    nlohmann::ordered_json j{{"fs_hz", rate.fs_hz}};
    const auto rad = radii(rate.model);
    if (std::any_of(rad.begin(), rad.end(), [](double v) { return !(v < 1.0); }))
      r.fail(fmt::format("fs {} Hz: a pole on or outside the unit circle (see discrete_stability): zero input does "
                         "not decay", rate.fs_hz));
    else if (fixed)
      fixed_zero_input(r, rate.fs_hz, rate.model, *rate.fixed, j);
    else
      float_zero_input(r, rate.fs_hz, rate.model, j);
    total += j.value("simulated_samples", 0L);
    rates.push_back(j);
  }
  r.details["rates"] = rates;
  r.summary = r.failures.empty() ? fmt::format("zero input decays to 0 at every rate ({} samples simulated)", total)
                                 : "zero input does not decay";
  return r;
}

}  // namespace admitgen::checks

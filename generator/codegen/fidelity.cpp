// SPDX-License-Identifier: MIT
#include "codegen/fidelity.hpp"

#include "model/multipole.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace admitgen::codegen {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Max of |H − G|/|G| over log-spaced f in [lo, hi] (n points), and where.
std::pair<double, double> max_deviation(const MultipoleSurface& model, const DiscreteModel& h, double lo, double hi,
                                        int n) {
  Eigen::ArrayXd f(n);
  for (int i = 0; i < n; ++i) f[i] = n == 1 ? lo : lo * std::pow(hi / lo, double(i) / (n - 1));
  const Eigen::ArrayXcd g = evaluate_multipole(model.order, model.theta, 2.0 * kPi * f);
  double worst = 0.0, at = lo;
  for (int i = 0; i < n; ++i) {
    const double d = std::abs(h.response(f[i]) - g[i]) / std::max(std::abs(g[i]), 1e-300);
    if (d > worst) worst = d, at = f[i];
  }
  return {worst, at};
}

/// N of the file comment.
double noise_floor(const DiscreteModel& h, const FixedCoefficients* fixed) {
  const double lsb_state = fixed ? std::ldexp(1.0, -31) : std::ldexp(1.0, -23);
  const double lsb_out = fixed ? std::ldexp(1.0, fixed->out_shift - data_bits(fixed->format)) : std::ldexp(1.0, -23);
  double gain = 0.0;
  for (const auto& r : h.real) gain += std::abs(r.c) / r.eps;
  for (const auto& p : h.pair) {
    const double decay = 1.0 - std::abs(std::complex<double>(1.0 + p.e_r, p.p_i));
    gain += 2.0 * std::sqrt(2.0) * std::abs(p.c) / decay;
  }
  return 0.5 * lsb_out + lsb_state * gain;
}

}  // namespace

Fidelity fidelity(const MultipoleSurface& model, const DiscreteModel& emitted, const FixedCoefficients* fixed,
                  double f_lo, double f_hi) {
  // The kernel's output scaling is part of what it computes: a header whose acc_shift disagrees with its
  // exponents outputs the response times output_gain().
  DiscreteModel h = emitted;
  if (fixed != nullptr) {
    const double k = fixed->output_gain();
    for (auto& d : h.fir) d *= k;
    for (auto& r : h.real) r.c *= k;
    for (auto& p : h.pair) p.c *= k;
  }
  Fidelity out;
  std::tie(out.max_rel_deviation, out.at_hz) = max_deviation(model, h, f_lo, f_hi, kFidelityPoints);
  if (const double top = 0.45 * h.fs_hz; top > f_hi)
    std::tie(out.max_rel_deviation_above, out.above_at_hz) = max_deviation(model, h, f_hi, top, kFidelityPoints / 4);
  out.noise_floor = noise_floor(h, fixed);
  out.min_snr_db = INFINITY;
  for (int i = 0; i < kFidelityPoints; ++i) {
    const double f = f_lo * std::pow(f_hi / f_lo, double(i) / (kFidelityPoints - 1));
    const double snr = 20.0 * std::log10(std::abs(h.response(f)) / out.noise_floor);
    if (snr < out.min_snr_db) out.min_snr_db = snr, out.snr_at_hz = f;
  }
  return out;
}

}  // namespace admitgen::codegen

// SPDX-License-Identifier: MIT
#include "codegen/fidelity.hpp"

#include "model/multipole.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace admitgen::codegen {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// n log-spaced frequencies over [lo, hi] (n ≥ 2).
Eigen::ArrayXd log_frequencies(double lo, double hi, int n) {
  Eigen::ArrayXd f(n);
  for (int i = 0; i < n; ++i) f[i] = lo * std::pow(hi / lo, double(i) / (n - 1));
  return f;
}

/// H at f and the max of |H − G|/|G| there, with where.
struct Deviation {
  Eigen::ArrayXcd h;
  double max = 0.0, at = 0.0;
};
Deviation deviation(const MultipoleSurface& model, const DiscreteModel& emitted, const Eigen::ArrayXd& f) {
  const Eigen::ArrayXcd g = evaluate_multipole(model.order, model.theta, 2.0 * kPi * f);
  Deviation d{Eigen::ArrayXcd(f.size()), 0.0, f.size() > 0 ? f[0] : 0.0};
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    d.h[i] = emitted.response(f[i]);
    const double r = std::abs(d.h[i] - g[i]) / std::max(std::abs(g[i]), 1e-300);
    if (r > d.max) d.max = r, d.at = f[i];
  }
  return d;
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
  const Eigen::ArrayXd band = log_frequencies(f_lo, f_hi, kFidelityPoints);
  const Deviation in_band = deviation(model, h, band);
  out.max_rel_deviation = in_band.max;
  out.at_hz = in_band.at;
  if (const double top = 0.45 * h.fs_hz; top > f_hi) {
    const Deviation above = deviation(model, h, log_frequencies(f_hi, top, kFidelityPoints / 4));
    out.max_rel_deviation_above = above.max;
    out.above_at_hz = above.at;
  }
  out.noise_floor = noise_floor(h, fixed);
  Eigen::Index weakest = 0;
  const double h_min = in_band.h.abs().minCoeff(&weakest);
  out.min_snr_db = 20.0 * std::log10(h_min / out.noise_floor);
  out.snr_at_hz = band[weakest];
  return out;
}

}  // namespace admitgen::codegen

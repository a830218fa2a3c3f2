// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"
#include "checks/passivity.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen::checks {
namespace {

std::string hz(double f) { return std::isinf(f) ? "infinity" : fmt::format("{:.6g} Hz", f); }

/// Where a band lies relative to the fitted data band [lo, hi].
BandPlace place(const NegativeBand& b, double lo, double hi) {
  if (!(hi > lo)) return BandPlace::data_band_unknown;
  if (b.hi < lo) return BandPlace::below;
  if (b.lo > hi) return BandPlace::above;
  if (b.lo >= lo && b.hi <= hi) return BandPlace::inside;
  return BandPlace::overlapping;
}

PassivityDetails details(PassivityResult p, double lo, double hi) {
  PassivityDetails d;
  for (const auto& b : p.bands) d.places.push_back(place(b, lo, hi));
  d.test = std::move(p);
  return d;
}

/// Fails r for every negative band, and for a model the test did not pass without naming a band (a minimum below
/// 0 never passes: docs/passivity.md, "What the certificate guarantees").
void report_bands(CheckResult& r, const PassivityResult& p, const std::string& prefix, double lo, double hi) {
  for (const auto& b : p.bands)
    r.fail(fmt::format("{}Re G < 0 from {} to {} ({}), min Re G = {:.4g} at {}", prefix, hz(b.lo), hz(b.hi),
                       band_place_text(place(b, lo, hi)), b.min_re, hz(b.at)));
  if (!p.passive && p.bands.empty())
    r.fail(fmt::format("{}min Re G = {:.4g} at {} is below 0", prefix, p.min_re, hz(p.min_at)));
}

}  // namespace

CheckResult check_continuous_passivity(const CheckSubject& s) {
  CheckResult r;
  r.name = "passivity_continuous";
  if (!is_causal(s.surface.order, s.surface.theta.data()))
    return r.not_applicable("not causal (see causality): positive-realness needs every pole in the left half-plane");
  const PassivityResult p = continuous_passivity(s.surface.order, s.surface.theta.data());
  r.method = "Re G(jw) >= 0 for all w >= 0: imaginary-axis eigenvalues of the Hamiltonian (" + p.method + ")";
  report_bands(r, p, "", s.data_f_min_hz, s.data_f_max_hz);
  r.summary = fmt::format("min Re G = {:.4g} at {}; {} crossing(s), {} negative band(s)", p.min_re, hz(p.min_at),
                          p.crossings.size(), p.bands.size());
  r.details = details(p, s.data_f_min_hz, s.data_f_max_hz);
  return r;
}

CheckResult check_discrete_passivity(const CheckSubject& s) {
  CheckResult r;
  r.name = "passivity_discrete";
  if (!s.header)
    return r.not_applicable("a fit has no emitted coefficients (check the header made by admitgen emit)");
  r.method = "Re H(e^jtheta) >= 0 on [0, pi] of the emitted (quantised) coefficients: Hamiltonian test after the "
             "bilinear map z = (1 + s)/(1 - s)";
  DiscretePassivityDetails d;
  double worst = std::numeric_limits<double>::infinity();
  std::string worst_text;
  for (const auto& rate : s.header->rates) {
    if (!rate.model.stable()) {
      d.rates.push_back({rate.fs_hz, std::nullopt});
      r.fail(fmt::format("fs {} Hz: not decidable, the filter is unstable (see discrete_stability)", rate.fs_hz));
      continue;
    }
    const PassivityResult p = discrete_passivity(rate.model);
    report_bands(r, p, fmt::format("fs {} Hz: ", rate.fs_hz), s.data_f_min_hz, s.data_f_max_hz);
    d.rates.push_back({rate.fs_hz, details(p, s.data_f_min_hz, s.data_f_max_hz)});
    if (p.min_re < worst) worst = p.min_re, worst_text = fmt::format("{} (fs {} Hz)", hz(p.min_at), rate.fs_hz);
  }
  r.details = d;
  r.summary = std::isfinite(worst) ? fmt::format("min Re H = {:.4g} at {}", worst, worst_text) : "no stable rate";
  return r;
}

}  // namespace admitgen::checks

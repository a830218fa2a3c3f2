// SPDX-License-Identifier: MIT
#include "checks/passivity.hpp"

#include "checks/state_space.hpp"

#include <cmath>
#include <limits>

namespace admitgen::checks {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

}  // namespace

PassivityResult discrete_passivity(const codegen::DiscreteModel& m, bool scan) {
  const StateSpace ss = bilinear_to_continuous(discrete_realisation(m));
  const double fs = m.fs_hz;
  // ω = tan(θ/2), θ = 2π f / fs  ⇔  f = fs atan(ω) / π.
  const auto hz = [fs](double w) { return w == kInf ? 0.5 * fs : fs * std::atan(w) / kPi; };
  const RealPartFn re = [&](double w) { return m.response(hz(w)).real(); };
  const double lo = std::tan(kPi * 1.0 / fs), hi = std::tan(0.5 * kPi * (1.0 - 1e-7));
  // Each pair's resonance in the bilinear frequency ω = tan(θ/2): centre tan(βT/2), half width
  // (αT/2)(1 + ω²) (dω/dθ = (1 + ω²)/2).
  std::vector<FeatureWindow> windows;
  for (const auto& p : m.pair) {
    const double theta = std::abs(p.beta) / fs;
    if (theta >= kPi) continue;
    const double centre = std::tan(0.5 * theta);
    windows.push_back({centre, 0.5 * (p.alpha / fs) * (1.0 + centre * centre)});
  }
  PassivityResult r = hamiltonian_passivity(ss, re, lo, hi, scan, windows);
  for (auto& c : r.crossings) c = hz(c);
  for (auto& b : r.bands) b.lo = hz(b.lo), b.hi = hz(b.hi), b.at = hz(b.at);
  r.min_at = hz(r.min_at);
  return r;
}

}  // namespace admitgen::checks

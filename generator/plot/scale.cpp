// SPDX-License-Identifier: MIT
#include "plot/scale.hpp"

#include "core/errors.hpp"
#include "plot/format.hpp"

#include <cmath>

namespace admitgen::plot {
namespace {

std::string label_for(double v, double step, LabelStyle style) {
  return style == LabelStyle::hertz ? hz_label(v) : tick_label(v, step);
}

}  // namespace

Scale::Scale(ScaleKind kind, double lo, double hi, double px_lo, double px_hi)
    : kind_(kind), lo_(lo), hi_(hi), px_lo_(px_lo), px_hi_(px_hi) {
  ADMITGEN_ENSURE(std::isfinite(lo) && std::isfinite(hi) && lo < hi, "scale range [{}, {}]", lo, hi);
  ADMITGEN_ENSURE(kind == ScaleKind::linear || lo > 0.0, "log scale needs a positive range, got [{}, {}]", lo, hi);
}

double Scale::operator()(double v) const {
  const double t = kind_ == ScaleKind::log ? std::log(v / lo_) / std::log(hi_ / lo_) : (v - lo_) / (hi_ - lo_);
  return px_lo_ + t * (px_hi_ - px_lo_);
}

bool Scale::contains(double v) const {
  const double slack = 1e-9 * (kind_ == ScaleKind::log ? v : (hi_ - lo_));
  return v >= lo_ - slack && v <= hi_ + slack;
}

std::vector<Tick> Scale::ticks(int target, LabelStyle style) const {
  return kind_ == ScaleKind::log ? log_ticks(style) : linear_ticks(target, style);
}

std::vector<Tick> Scale::linear_ticks(int target, LabelStyle style) const {
  const double step = nice_step(hi_ - lo_, target);
  std::vector<Tick> out;
  for (double k = std::ceil(lo_ / step - 1e-9); k * step <= hi_ + 1e-9 * step; k += 1.0) {
    const double v = k * step;
    out.push_back({v, label_for(v, step, style), true});
  }
  return out;
}

std::vector<Tick> Scale::log_ticks(LabelStyle style) const {
  const double decades = std::log10(hi_ / lo_);
  // Mantissas that get a label: every decade only on wide axes, 1-2-5 on medium ones, all on narrow ones.
  const auto labelled = [decades](int m) {
    if (decades > 3.5) return m == 1;
    if (decades > 1.2) return m == 1 || m == 2 || m == 5;
    return true;
  };
  std::vector<Tick> out;
  for (int e = static_cast<int>(std::floor(std::log10(lo_))); e <= static_cast<int>(std::ceil(std::log10(hi_))); ++e) {
    const double base = std::pow(10.0, e);
    for (int m = 1; m <= 9; ++m) {
      const double v = m * base;
      if (!contains(v)) continue;
      const bool major = labelled(m);
      out.push_back({v, major ? label_for(v, base, style) : std::string{}, major});
    }
  }
  return out;
}

double nice_step(double span, int target) {
  ADMITGEN_ENSURE(span > 0.0 && target > 0, "nice_step({}, {})", span, target);
  const double raw = span / target;
  const double base = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0})
    if (raw <= m * base * 1.1) return m * base;
  return 10.0 * base;
}

void nice_range(ScaleKind kind, double& lo, double& hi, int target) {
  if (kind == ScaleKind::log) {
    if (!(hi > lo)) {
      lo /= 2.0;
      hi *= 2.0;
    }
    const double pad = std::pow(hi / lo, 0.02);
    lo /= pad;
    hi *= pad;
    return;
  }
  if (!(hi > lo)) {
    const double w = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= w;
    hi += w;
  }
  const double step = nice_step(hi - lo, target);
  lo = std::floor(lo / step + 1e-9) * step;
  hi = std::ceil(hi / step - 1e-9) * step;
}

}  // namespace admitgen::plot

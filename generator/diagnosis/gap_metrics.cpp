// SPDX-License-Identifier: MIT
#include "diagnosis/gap_metrics.hpp"

#include "core/errors.hpp"
#include "data/measurement.hpp"

#include <cmath>

namespace admitgen::diagnosis {
namespace {

double rms(const Eigen::ArrayXd& squares) { return std::sqrt(squares.mean()); }

}  // namespace

double rms_level(const Eigen::ArrayXcd& y) { return std::sqrt(y.abs2().mean()); }

Gap measure_gap(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real, const Eigen::ArrayXcd& y_model,
                double level) {
  ADMITGEN_ENSURE(f_hz.size() == y_real.size() && y_real.size() == y_model.size() && f_hz.size() >= 2,
                  "gap needs matching arrays of at least two points ({}, {}, {})", f_hz.size(), y_real.size(),
                  y_model.size());
  ADMITGEN_ENSURE(level > 0.0 && std::isfinite(level), "the admittance level must be positive, got {}", level);
  const Eigen::ArrayXcd r = y_real - y_model;
  const Eigen::ArrayXd re2 = r.real().square();
  const Eigen::ArrayXd im2 = r.imag().square();
  const Eigen::ArrayXd dalpha = (absorption(y_real) - absorption(y_model)).abs();

  Gap g;
  g.total = rms(re2 + im2) / level;
  g.total_re = rms(re2) / level;
  g.total_im = rms(im2) / level;
  g.delta_alpha_max = dalpha.maxCoeff();
  g.whiteness = residual_whiteness(r);
  for (const auto& band : covered_bands(f_hz)) {
    BandGap b;
    b.band = band;
    const auto seg = [&](const Eigen::ArrayXd& a) { return a.segment(band.first, band.count); };
    b.gap = rms(seg(re2) + seg(im2)) / level;
    b.gap_re = rms(seg(re2)) / level;
    b.gap_im = rms(seg(im2)) / level;
    b.delta_alpha_max = seg(dalpha).maxCoeff();
    g.bands.push_back(b);
  }
  ADMITGEN_ENSURE(!g.bands.empty(), "no one-third-octave band covered by {}-{} Hz", f_hz[0], f_hz[f_hz.size() - 1]);
  for (std::size_t i = 1; i < g.bands.size(); ++i)
    if (g.bands[i].gap > g.bands[g.worst].gap) g.worst = i;
  return g;
}

std::size_t most_improved_band(const std::vector<BandGap>& before, const std::vector<BandGap>& after) {
  ADMITGEN_ENSURE(before.size() == after.size() && !before.empty(), "band lists differ ({} vs {})", before.size(),
                  after.size());
  std::size_t best = 0;
  double best_gain = -1.0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const double gain = before[i].gap * before[i].gap - after[i].gap * after[i].gap;
    if (gain > best_gain) {
      best_gain = gain;
      best = i;
    }
  }
  return best;
}

}  // namespace admitgen::diagnosis

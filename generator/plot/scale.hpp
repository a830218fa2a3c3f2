// SPDX-License-Identifier: MIT
/// @file
/// Axis scales: a map from data values to pixels, and the tick positions and labels that go with it.
/// Linear ticks sit on the 1-2-2.5-5 × 10^k grid (Heckbert, "Nice numbers for graph labels",
/// Graphics Gems, 1990); log ticks on decades, with 2 and 5 labelled when the axis spans few decades.
#pragma once

#include <string>
#include <vector>

namespace admitgen::plot {

enum class ScaleKind { linear, log };

struct Tick {
  double value;
  std::string label;  ///< empty for an unlabelled minor tick
  bool major;         ///< major ticks get a grid line
};

/// How tick labels read: plain numbers, or frequencies in Hz (1k, 2.5k).
enum class LabelStyle { plain, hertz };

class Scale {
 public:
  /// Maps [lo, hi] (lo < hi; both > 0 for log) onto pixels [px_lo, px_hi] (px_hi < px_lo for a y axis).
  Scale(ScaleKind kind, double lo, double hi, double px_lo, double px_hi);

  double operator()(double v) const;
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  ScaleKind kind() const { return kind_; }
  bool contains(double v) const;

  /// About `target` labelled ticks inside [lo, hi].
  std::vector<Tick> ticks(int target, LabelStyle style) const;

 private:
  std::vector<Tick> linear_ticks(int target, LabelStyle style) const;
  std::vector<Tick> log_ticks(LabelStyle style) const;

  ScaleKind kind_;
  double lo_, hi_, px_lo_, px_hi_;
};

/// The smallest "nice" step (1, 2, 2.5 or 5 × 10^k) not below span / target (with 10 % slack), so
/// that about `target` steps, never many more, cover the span.
double nice_step(double span, int target);

/// [lo, hi] widened to the enclosing multiples of nice_step (linear), or padded by 2 % of the decades
/// (log). Degenerate ranges (lo == hi) are widened around the value.
void nice_range(ScaleKind kind, double& lo, double& hi, int target);

}  // namespace admitgen::plot

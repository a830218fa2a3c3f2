// SPDX-License-Identifier: MIT
/// @file
/// A small SVG chart: one plot area with x and y axes (linear, log or categorical), series of lines,
/// markers, shaded bands, error bars and bars, and a legend above the plot area.
///
/// Colours are not written into the SVG: elements carry classes (`tone-data`, `tone-c1` … `tone-c4`,
/// `axis`, `grid`) that the page styles with CSS variables, so one SVG reads on light, dark and
/// printed pages (report/report_style.hpp holds the stylesheet). Every number goes through
/// plot/format.hpp, so equal inputs give byte-identical SVG. Non-finite values are skipped: a line
/// or band breaks there instead of drawing to NaN.
#pragma once

#include "plot/scale.hpp"

#include <optional>
#include <string>
#include <vector>

namespace admitgen::plot {

struct Axis {
  std::string label;
  ScaleKind kind = ScaleKind::linear;
  LabelStyle style = LabelStyle::plain;
  std::optional<double> lo, hi;         ///< fixed limits; otherwise from the data, widened to nice values
  bool include_zero = false;            ///< widen the automatic range to contain 0 (linear only)
  std::vector<std::string> categories;  ///< non-empty: categorical axis, category i at x = i
  std::vector<Tick> ticks;              ///< non-empty: these ticks instead of the automatic ones
};

enum class SeriesKind { line, markers, band, error_bars, bars };

/// One data series. Which vectors are used depends on the kind:
/// line, markers: x, y; band: x, lo, hi; error_bars: x, y, lo, hi; bars: x (left edge), x_hi, y.
struct Series {
  SeriesKind kind;
  std::string name;   ///< machine name, written as data-series (e.g. "data", "model", "band")
  std::string label;  ///< legend text; empty = not in the legend
  std::string tone;   ///< "data" or "c1" … "c4" (CSS class tone-…)
  std::vector<double> x, y, lo, hi, x_hi;
  bool dashed = false;
};

Series line(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> y);
Series markers(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> y);
Series band(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> lo,
            std::vector<double> hi);
Series error_bars(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> y,
                  std::vector<double> lo, std::vector<double> hi);
Series bars(std::string name, std::string label, std::string tone, std::vector<double> x_lo, std::vector<double> x_hi,
            std::vector<double> y);

class Figure {
 public:
  /// `id` must be unique within the page (it prefixes the clip path's id); `title` is the SVG
  /// <title>, read by screen readers.
  Figure(std::string id, std::string title, double width = 720.0, double height = 330.0);

  Axis x, y;

  void add(Series series);
  const std::vector<Series>& series() const { return series_; }

  /// The chart as a standalone SVG element (with xmlns), ready to inline in HTML.
  std::string svg() const;

 private:
  struct Frame;
  Frame frame() const;

  std::string id_, title_;
  double width_, height_;
  std::vector<Series> series_;
};

}  // namespace admitgen::plot

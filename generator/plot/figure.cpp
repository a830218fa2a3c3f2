// SPDX-License-Identifier: MIT
#include "plot/figure.hpp"

#include "core/errors.hpp"
#include "plot/format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen::plot {
namespace {

constexpr double kLeft = 72.0, kRight = 18.0, kTop = 36.0, kBottom = 50.0;
constexpr double kMarkerRadius = 2.2, kCharWidth = 6.6;

/// Finite values (and positive ones on a log axis) that fix an automatic range.
struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v, ScaleKind kind) {
    if (!std::isfinite(v) || (kind == ScaleKind::log && v <= 0.0)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  void add(const std::vector<double>& vs, ScaleKind kind) {
    for (const double v : vs) add(v, kind);
  }
};

/// Characters (UTF-8 code points) of a label, for its approximate width in the legend.
double text_length(const std::string& text) {
  return static_cast<double>(std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

bool usable(double v, const Scale& s) { return std::isfinite(v) && (s.kind() == ScaleKind::linear || v > 0.0); }

Scale make_scale(const Axis& axis, Extent e, double px_lo, double px_hi, int target) {
  if (!axis.categories.empty())
    return Scale(ScaleKind::linear, -0.5, static_cast<double>(axis.categories.size()) - 0.5, px_lo, px_hi);
  if (axis.include_zero && axis.kind == ScaleKind::linear) e.add(0.0, ScaleKind::linear);
  if (!std::isfinite(e.lo)) e.lo = e.hi = axis.kind == ScaleKind::log ? 1.0 : 0.0;
  double lo = e.lo, hi = e.hi;
  nice_range(axis.kind, lo, hi, target);
  return Scale(axis.kind, axis.lo.value_or(lo), axis.hi.value_or(hi), px_lo, px_hi);
}

std::string class_of(const Series& s) {
  static const char* const kinds[] = {"line", "markers", "band", "error-bars", "bars"};
  return fmt::format("series tone-{} kind-{}{}", s.tone, kinds[static_cast<int>(s.kind)], s.dashed ? " dashed" : "");
}

/// "M x y L x y …" over runs of consecutive usable points; a gap starts a new run.
std::string polyline_path(const std::vector<double>& xs, const std::vector<double>& ys, const Scale& sx, const Scale& sy) {
  std::string d;
  bool pen_down = false;
  for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
    if (!usable(xs[i], sx) || !usable(ys[i], sy)) {
      pen_down = false;
      continue;
    }
    d += fmt::format("{}{} {}", d.empty() ? "M" : (pen_down ? " L" : " M"), coord(sx(xs[i])), coord(sy(ys[i])));
    pen_down = true;
  }
  return d;
}

/// Closed outlines of the band between lo and hi, one per run of usable points.
std::string band_path(const Series& s, const Scale& sx, const Scale& sy) {
  std::string d;
  std::size_t i = 0;
  const std::size_t n = std::min({s.x.size(), s.lo.size(), s.hi.size()});
  const auto ok = [&](std::size_t k) { return usable(s.x[k], sx) && usable(s.lo[k], sy) && usable(s.hi[k], sy); };
  while (i < n) {
    if (!ok(i)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && ok(j)) ++j;
    for (std::size_t k = i; k < j; ++k)
      d += fmt::format("{}{} {}", k == i ? (d.empty() ? "M" : " M") : " L", coord(sx(s.x[k])), coord(sy(s.hi[k])));
    for (std::size_t k = j; k-- > i;) d += fmt::format(" L{} {}", coord(sx(s.x[k])), coord(sy(s.lo[k])));
    d += " Z";
    i = j;
  }
  return d;
}

std::string render_series(const Series& s, const Scale& sx, const Scale& sy) {
  std::string out = fmt::format("<g class=\"{}\" data-series=\"{}\">", class_of(s), escape_xml(s.name));
  switch (s.kind) {
    case SeriesKind::line: {
      const std::string d = polyline_path(s.x, s.y, sx, sy);
      if (!d.empty()) out += fmt::format("<path d=\"{}\" fill=\"none\"/>", d);
      break;
    }
    case SeriesKind::band: {
      const std::string d = band_path(s, sx, sy);
      if (!d.empty()) out += fmt::format("<path d=\"{}\" stroke=\"none\"/>", d);
      break;
    }
    case SeriesKind::markers:
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
        if (usable(s.x[i], sx) && usable(s.y[i], sy))
          out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>", coord(sx(s.x[i])), coord(sy(s.y[i])),
                             coord(kMarkerRadius));
      break;
    case SeriesKind::error_bars:
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (!usable(s.x[i], sx) || !usable(s.y[i], sy) || !usable(s.lo[i], sy) || !usable(s.hi[i], sy)) continue;
        const std::string x = coord(sx(s.x[i]));
        const double cap = 5.0;
        out += fmt::format("<path d=\"M{0} {1} L{0} {2} M{3} {1} L{4} {1} M{3} {2} L{4} {2}\" fill=\"none\"/>", x,
                           coord(sy(s.lo[i])), coord(sy(s.hi[i])), coord(sx(s.x[i]) - cap), coord(sx(s.x[i]) + cap));
        out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>", x, coord(sy(s.y[i])), coord(1.6 * kMarkerRadius));
      }
      break;
    case SeriesKind::bars: {
      const double base = sy(sy.kind() == ScaleKind::log ? sy.lo() : std::clamp(0.0, sy.lo(), sy.hi()));
      for (std::size_t i = 0; i < s.x.size() && i < s.x_hi.size() && i < s.y.size(); ++i) {
        if (!usable(s.x[i], sx) || !usable(s.x_hi[i], sx) || !usable(s.y[i], sy)) continue;
        const double x0 = sx(s.x[i]), x1 = sx(s.x_hi[i]), top = sy(s.y[i]);
        out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>", coord(std::min(x0, x1)),
                           coord(std::min(top, base)), coord(std::abs(x1 - x0)), coord(std::abs(base - top)));
      }
      break;
    }
  }
  return out + "</g>";
}

/// A legend swatch drawn like the series it stands for, 22 px wide, centred on (x + 11, y).
std::string swatch(const Series& s, double x, double y) {
  const std::string cls = class_of(s);
  switch (s.kind) {
    case SeriesKind::line:
      return fmt::format("<g class=\"{}\"><path d=\"M{} {} L{} {}\" fill=\"none\"/></g>", cls, coord(x), coord(y),
                         coord(x + 22), coord(y));
    case SeriesKind::band:
    case SeriesKind::bars:
      return fmt::format("<g class=\"{}\"><rect x=\"{}\" y=\"{}\" width=\"22\" height=\"10\"/></g>", cls, coord(x),
                         coord(y - 5));
    case SeriesKind::markers:
    case SeriesKind::error_bars:
      return fmt::format("<g class=\"{}\"><circle cx=\"{}\" cy=\"{}\" r=\"{}\"/></g>", cls, coord(x + 11), coord(y),
                         coord(s.kind == SeriesKind::markers ? 3.0 : 1.6 * kMarkerRadius));
  }
  return {};
}

}  // namespace

Series line(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> y) {
  return Series{SeriesKind::line, std::move(name), std::move(label), std::move(tone), std::move(x), std::move(y), {}, {}, {}};
}

Series markers(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> y) {
  return Series{SeriesKind::markers, std::move(name), std::move(label), std::move(tone), std::move(x), std::move(y), {}, {}, {}};
}

Series band(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> lo,
            std::vector<double> hi) {
  return Series{SeriesKind::band, std::move(name), std::move(label), std::move(tone), std::move(x), {}, std::move(lo),
                std::move(hi), {}};
}

Series error_bars(std::string name, std::string label, std::string tone, std::vector<double> x, std::vector<double> y,
                  std::vector<double> lo, std::vector<double> hi) {
  return Series{SeriesKind::error_bars, std::move(name), std::move(label), std::move(tone), std::move(x), std::move(y),
                std::move(lo), std::move(hi), {}};
}

Series bars(std::string name, std::string label, std::string tone, std::vector<double> x_lo, std::vector<double> x_hi,
            std::vector<double> y) {
  return Series{SeriesKind::bars, std::move(name), std::move(label), std::move(tone), std::move(x_lo), std::move(y), {}, {},
                std::move(x_hi)};
}

struct Figure::Frame {
  Scale sx, sy;
};

Figure::Figure(std::string id, std::string title, double width, double height)
    : id_(std::move(id)), title_(std::move(title)), width_(width), height_(height) {}

void Figure::add(Series series) {
  const std::size_t n = series.x.size();
  const bool y_ok = series.kind == SeriesKind::band || series.y.size() == n;
  const bool band_ok = (series.kind != SeriesKind::band && series.kind != SeriesKind::error_bars) ||
                       (series.lo.size() == n && series.hi.size() == n);
  ADMITGEN_ENSURE(y_ok && band_ok && (series.kind != SeriesKind::bars || series.x_hi.size() == n),
                  "series '{}' has vectors of different lengths", series.name);
  series_.push_back(std::move(series));
}

Figure::Frame Figure::frame() const {
  Extent ex, ey;
  for (const auto& s : series_) {
    ex.add(s.x, x.kind);
    ex.add(s.x_hi, x.kind);
    ey.add(s.y, y.kind);
    ey.add(s.lo, y.kind);
    ey.add(s.hi, y.kind);
  }
  return Frame{make_scale(x, ex, kLeft, width_ - kRight, 8), make_scale(y, ey, height_ - kBottom, kTop, 5)};
}

std::string Figure::svg() const {
  const Frame f = frame();
  const double left = kLeft, right = width_ - kRight, top = kTop, bottom = height_ - kBottom;
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"ag-plot\" id=\"{0}\" viewBox=\"0 0 {1} {2}\" width=\"{1}\" "
      "height=\"{2}\" role=\"img\" aria-labelledby=\"{0}-title\" font-size=\"12\">"
      "<title id=\"{0}-title\">{3}</title>"
      "<defs><clipPath id=\"{0}-clip\"><rect x=\"{4}\" y=\"{5}\" width=\"{6}\" height=\"{7}\"/></clipPath></defs>",
      escape_xml(id_), coord(width_), coord(height_), escape_xml(title_), coord(left), coord(top), coord(right - left),
      coord(bottom - top));

  // Grid and ticks.
  std::string grid = "<g class=\"grid\">", axis = "<g class=\"axis\">";
  std::vector<Tick> xt = x.ticks;
  if (!xt.empty()) {
    xt.erase(std::remove_if(xt.begin(), xt.end(), [&f](const Tick& t) { return !f.sx.contains(t.value); }), xt.end());
  } else if (x.categories.empty()) {
    xt = f.sx.ticks(8, x.style);
  } else {
    for (std::size_t i = 0; i < x.categories.size(); ++i) xt.push_back({static_cast<double>(i), x.categories[i], false});
  }
  for (const auto& t : xt) {
    const std::string px = coord(f.sx(t.value));
    if (t.major) grid += fmt::format("<path d=\"M{0} {1} L{0} {2}\"/>", px, coord(top), coord(bottom));
    axis += fmt::format("<path d=\"M{0} {1} L{0} {2}\"/>", px, coord(bottom), coord(bottom + (t.label.empty() ? 3 : 5)));
    if (!t.label.empty())
      axis += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>", px, coord(bottom + 18),
                          escape_xml(t.label));
  }
  for (const auto& t : f.sy.ticks(5, y.style)) {
    const std::string py = coord(f.sy(t.value));
    if (t.major) grid += fmt::format("<path d=\"M{1} {0} L{2} {0}\"/>", py, coord(left), coord(right));
    axis += fmt::format("<path d=\"M{1} {0} L{2} {0}\"/>", py, coord(left - (t.label.empty() ? 3 : 5)), coord(left));
    if (!t.label.empty())
      axis += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>", coord(left - 8), coord(f.sy(t.value) + 4),
                          escape_xml(t.label));
  }
  axis += fmt::format("<rect class=\"frame\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\"/>", coord(left),
                      coord(top), coord(right - left), coord(bottom - top));
  axis += fmt::format("<text class=\"label\" x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>", coord((left + right) / 2),
                      coord(height_ - 10), escape_xml(x.label));
  axis += fmt::format("<text class=\"label\" x=\"{0}\" y=\"{1}\" text-anchor=\"middle\" transform=\"rotate(-90 {0} {1})\">{2}</text>",
                      coord(16), coord((top + bottom) / 2), escape_xml(y.label));
  out += grid + "</g>";

  out += fmt::format("<g class=\"data-area\" clip-path=\"url(#{}-clip)\">", escape_xml(id_));
  for (const auto& s : series_) out += render_series(s, f.sx, f.sy);
  out += "</g>" + axis + "</g>";

  // Legend: one row above the plot area, left-aligned with it.
  out += "<g class=\"legend\">";
  double lx = left;
  for (const auto& s : series_) {
    if (s.label.empty()) continue;
    out += swatch(s, lx, top - 16);
    out += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>", coord(lx + 28), coord(top - 12), escape_xml(s.label));
    lx += 28 + kCharWidth * text_length(s.label) + 18;
  }
  return out + "</g></svg>";
}

}  // namespace admitgen::plot

// SPDX-License-Identifier: MIT
#include "plot/format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace admitgen::plot {
namespace {

/// Removes trailing zeros (and a trailing point) of a fixed-point string.
std::string trim_zeros(std::string s) {
  if (s.find('.') == std::string::npos) return s;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::string without_negative_zero(std::string s) {
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("0.", 1) == std::string::npos) s.erase(0, 1);
  return s;
}

/// A leading hyphen-minus as U+2212 MINUS SIGN, the sign typeset in figure labels.
std::string typographic_minus(std::string s) {
  if (!s.empty() && s[0] == '-') s.replace(0, 1, "\u2212");
  return s;
}

}  // namespace

std::string coord(double v) { return without_negative_zero(trim_zeros(fmt::format("{:.2f}", v))); }

std::string tick_label(double v, double step) {
  const double a = std::abs(v);
  if (a != 0.0 && (a >= 1e4 || a < 1e-3)) return typographic_minus(without_negative_zero(fmt::format("{:g}", v)));
  // Decimals needed to show multiples of step exactly (step is 1, 2, 2.5 or 5 times a power of ten).
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (std::abs(step / std::pow(10.0, std::floor(std::log10(step) + 1e-9)) - 2.5) < 1e-6) ++decimals;
  return typographic_minus(without_negative_zero(fmt::format("{:.{}f}", v, decimals)));
}

std::string hz_label(double f) {
  if (f >= 1000.0) return trim_zeros(fmt::format("{:.2f}", f / 1000.0)) + "k";
  return trim_zeros(fmt::format("{:.2f}", f));
}

std::string json_number(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".en") == std::string::npos) s += ".0";  // "1e-05", "inf", "nan" stay as they are
  return s;
}

std::string number(double v, int digits) {
  if (!std::isfinite(v)) return std::isnan(v) ? "NaN" : (v > 0 ? "∞" : "−∞");
  const double a = std::abs(v);
  if (a == 0.0) return "0";
  if (a < 1e-3 || a >= 1e6) return without_negative_zero(fmt::format("{:.{}g}", v, digits));
  const int magnitude = static_cast<int>(std::floor(std::log10(a)));
  const int decimals = std::max(0, digits - 1 - magnitude);
  return without_negative_zero(trim_zeros(fmt::format("{:.{}f}", v, decimals)));
}

std::string frequency(double f_hz) {
  return std::abs(f_hz) >= 1000.0 ? number(f_hz / 1000.0, 3) + " kHz" : number(f_hz, 3) + " Hz";
}

double nominal_band(double f_center) {
  static constexpr double kR10[] = {1.0, 1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0, 10.0};
  const double decade = std::pow(10.0, std::floor(std::log10(f_center)));
  double best = kR10[0];
  for (const double m : kR10)
    if (std::abs(std::log(f_center / (m * decade))) < std::abs(std::log(f_center / (best * decade)))) best = m;
  return best * decade;
}

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace admitgen::plot

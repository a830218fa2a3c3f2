// SPDX-License-Identifier: MIT
/// @file
/// Deterministic text for SVG and HTML: numbers print the same bytes on every platform and locale
/// (fmt never consults the C locale), so equal inputs give byte-identical reports.
#pragma once

#include <string>
#include <string_view>

namespace admitgen::plot {

/// A coordinate in user units (pixels): two decimals, trailing zeros trimmed, −0 printed as 0.
std::string coord(double v);

/// A tick label for `v` on a grid of spacing `step`: as many decimals as the step needs
/// (step 0.25 → "0.75", step 20 → "40"), −0 printed as 0, values ≥ 10⁴ or < 10⁻³ in e-notation, a negative sign as U+2212.
std::string tick_label(double v, double step);

/// A frequency in Hz for a log axis: 50, 125, 1k, 2.5k, 10k.
std::string hz_label(double f);

/// A readable number with `digits` significant digits, for tables and captions: fixed notation for
/// 10⁻³ ≤ |v| < 10⁶ (2970, not 2.97e+03; trailing zeros dropped, 100 not 100.0), e-notation outside;
/// −0 as 0.
std::string number(double v, int digits = 4);

/// A number as the JSON files print it (shortest digits that read back exactly; integral values keep
/// ".0": 0.01, 413.3, 100.0), for quoting settings as the user finds them in fit.json.
std::string json_number(double v);

/// A frequency with 3 significant digits and its unit: 243 Hz, 9.34 kHz.
std::string frequency(double f_hz);

/// The nominal one-third-octave band name of an exact base-10 centre (IEC 61260-1 Annex E, the R10
/// preferred numbers 1, 1.25, 1.6, 2, 2.5, 3.15, 4, 5, 6.3, 8 × 10^k): 631 → 630, 1259 → 1250.
double nominal_band(double f_center);

/// Escapes &, <, >, " and ' for XML text and attribute values.
std::string escape_xml(std::string_view text);

}  // namespace admitgen::plot

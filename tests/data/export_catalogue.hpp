// SPDX-License-Identifier: MIT
/// @file
/// A catalogue of realistic exports of one measurement, written by the tests themselves: the ways
/// spreadsheets and impedance-tube software write a table (docs/reading-data.md). Each entry either
/// reads back to the reference admittance or fails with the documented message. Shared by the
/// reader test (in-process, numbers compared) and the CLI test (exit code 2, nothing written).
#pragma once

#include "data/read_options.hpp"
#include "model/multipole.hpp"

#include <Eigen/Core>
#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace admitgen::test {

struct Export {
  const char* name;
  const char* file;       ///< file name (extension as the software would write it)
  std::string text;       ///< file content
  ReadOptions options;    ///< how the in-process test reads it
  std::string flags;      ///< the same options on the command line
  std::string error;      ///< empty: reads to the reference; else text the error message contains
};

/// The reference: the Q1S1 truth of samples/reference (Ginf 0.469, A1 −26062, λ1 55250, B1 2019,
/// C1 −263, α1 1530, β1 10063; e^{+jωt}, normalised) at 41 log-spaced frequencies 100–4000 Hz, the
/// row count of a Basotect re-export.
struct Reference {
  Eigen::ArrayXd f;
  Eigen::ArrayXcd y;
  Reference() : f(Eigen::ArrayXd::LinSpaced(41, std::log(100.0), std::log(4000.0)).exp()) {
    Eigen::VectorXd theta(7);
    theta << 0.469, -26062, 55250, 2019, -263, 1530, 10063;
    y = evaluate_multipole(Order(1, 1), theta, 2.0 * EIGEN_PI * f);
  }
};

inline constexpr double kRhoC = 413.3;

/// Every number with 17 significant digits, so a written value parses back to the same double.
inline std::string g17(double v) { return fmt::format("{:.17g}", v); }
inline std::string comma(std::string s) {
  for (char& c : s)
    if (c == '.') c = ',';
  return s;
}

/// One line per frequency: `row(i)` gives the fields after the frequency.
inline std::string table(const Reference& r, const std::string& sep, const std::function<std::vector<std::string>(Eigen::Index)>& row,
                         const std::string& eol = "\n", bool decimal_comma = false) {
  std::string out;
  for (Eigen::Index i = 0; i < r.f.size(); ++i) {
    std::string line = decimal_comma ? comma(g17(r.f[i])) : g17(r.f[i]);
    for (const auto& field : row(i)) line += sep + (decimal_comma ? comma(field) : field);
    out += line + eol;
  }
  return out;
}

inline std::vector<Export> export_catalogue(const Reference& r) {
  const auto z = [&](Eigen::Index i) { return 1.0 / r.y[i]; };
  const auto refl = [&](Eigen::Index i) { return (1.0 - r.y[i]) / (1.0 + r.y[i]); };
  const auto parts = [](std::complex<double> v) { return std::vector<std::string>{g17(v.real()), g17(v.imag())}; };
  const auto alpha = [&](Eigen::Index i) { return std::vector<std::string>{g17(1.0 - std::norm(refl(i)))}; };
  const auto mag_db_deg = [&](Eigen::Index i) {
    return std::vector<std::string>{g17(20.0 * std::log10(std::abs(refl(i)))), g17(std::arg(refl(i)) * 180.0 / M_PI)};
  };
  const auto opts = [](auto&& set) {
    ReadOptions o;
    set(o);
    return o;
  };
  const auto polar_reflection = [](PhaseUnit unit) {  // mag/phase of R by position, no header
    ReadOptions o;
    o.columns = ColumnMap::parse("f,mag,phase");
    o.quantity = Quantity::reflection;
    o.phase = unit;
    return o;
  };
  std::vector<Export> c;
  c.push_back({"plain reference (f,re,im admittance)", "plain.csv", table(r, ",", [&](auto i) { return parts(r.y[i]); }),
               {}, "", ""});
  c.push_back({"European spreadsheet: ';', decimal comma, Re(Z/Z0) header", "europe.csv",
               "Frequency [Hz];Re(Z/Z0);Im(Z/Z0)\n" + table(r, ";", [&](auto i) { return parts(z(i)); }, "\n", true), {}, "",
               ""});
  c.push_back({"European, BOM, CRLF, trailing ';', admittance header", "europe_crlf.csv",
               "\xEF\xBB\xBF" "Frequenz [Hz];Re(y);Im(y);\r\n" +
                   table(r, ";", [&](auto i) { auto p = parts(r.y[i]); p.push_back(""); return p; }, "\r\n", true),
               {}, "", ""});
  c.push_back({"',' delimiter with quoted decimal-comma numbers (LibreOffice)", "quoted_comma.csv",
               "Frequency,Re(y),Im(y)\n" + [&] {
                 const auto q = [](double v) { return '"' + comma(g17(v)) + '"'; };
                 std::string out;
                 for (Eigen::Index i = 0; i < r.f.size(); ++i)
                   out += q(r.f[i]) + "," + q(r.y[i].real()) + "," + q(r.y[i].imag()) + "\n";
                 return out;
               }(),
               {}, "", ""});
  c.push_back({"US CSV, quoted header and units row", "us_units.csv",
               "\"Frequency\",\"Re(Z)\",\"Im(Z)\"\n\"Hz\",\"-\",\"-\"\n" + table(r, ",", [&](auto i) { return parts(z(i)); }),
               {}, "", ""});
  c.push_back({"tube software: preamble, tab-separated, Specific_Resistance_Ratio", "tube_export.txt",
               "Impedance tube measurement (ISO 10534-2)\nSample:\tBasotect 50 mm\nDate:\t2024-03-12\n"
               "Tube diameter [mm]:\t100\nTemperature [C]:\t21.3\n\n"
               "Frequency (Hz)\tSpecific_Resistance_Ratio\tSpecific_Reactance_Ratio\n" +
                   table(r, "\t", [&](auto i) { return parts(z(i)); }),
               {}, "", ""});
  c.push_back({"reflection factor magnitude [dB] and phase [deg]", "r_db_deg.csv",
               "Frequency [Hz],|R| [dB],Phase(R) [deg]\n" + table(r, ",", mag_db_deg), {}, "", ""});
  c.push_back({"reflection factor mag/phase by position, radians", "r_lin_rad.txt",
               table(r, " ", [&](auto i) { return std::vector<std::string>{g17(std::abs(refl(i))), g17(std::arg(refl(i)))}; }),
               polar_reflection(PhaseUnit::radians),
               "--columns f,mag,phase --quantity reflection --phase-unit rad", ""});
  c.push_back({"reflection factor re/im, Basotect-style names", "r_reim.csv",
               "freq,Re_R,Im_R\n" + table(r, ",", [&](auto i) { return parts(refl(i)); }), {}, "", ""});
  c.push_back({"SI impedance [Pa s/m] with --rho-c", "z_si.csv",
               "f [Hz],Re Z [Pa s/m],Im Z [Pa s/m]\n" + table(r, ",", [&](auto i) { return parts(kRhoC * z(i)); }),
               opts([](ReadOptions& o) { o.rho_c = kRhoC; }), "--rho-c 413.3", ""});
  c.push_back({"SI impedance [Pa s/m] without --rho-c", "z_si_no_rhoc.csv",
               "f [Hz],Re Z [Pa s/m],Im Z [Pa s/m]\n" + table(r, ",", [&](auto i) { return parts(kRhoC * z(i)); }), {}, "",
               "in SI units (Pa s/m or m/(Pa s)): give --rho-c RHO_C"});
  c.push_back({"SI impedance, no units, --quantity impedance without --rho-c", "z_si_silent.csv",
               table(r, ",", [&](auto i) { return parts(kRhoC * z(i)); }),
               opts([](ReadOptions& o) { o.quantity = Quantity::impedance; }), "--quantity impedance",
               "the values look like SI units or the wrong quantity, or the surface is almost rigid (alpha < 0.13 "
               "everywhere); read as --quantity impedance --rho-c RHO_C"});
  c.push_back({"SI impedance, no units, --rho-c without --quantity impedance", "z_si_as_y.csv",
               table(r, ",", [&](auto i) { return parts(kRhoC * z(i)); }), opts([](ReadOptions& o) { o.rho_c = kRhoC; }),
               "--rho-c 413.3", "read as --quantity impedance --rho-c 413.3, they are plausible"});
  c.push_back({"e^{-iwt} impedance with --time-convention -jwt", "z_minus.csv",
               "f,Re(Z/Z0),Im(Z/Z0)\n" + table(r, ",", [&](auto i) { return parts(std::conj(z(i))); }),
               opts([](ReadOptions& o) { o.time_convention = TimeConvention::minus_jwt; }), "--time-convention -jwt", ""});
  c.push_back({"e^{-iwt} impedance without --time-convention", "z_minus_silent.csv",
               "f,Re(Z/Z0),Im(Z/Z0)\n" + table(r, ",", [&](auto i) { return parts(std::conj(z(i))); }), {}, "",
               "The file probably uses the other time convention: give --time-convention -jwt"});
  // A series R-L wall, y = 1/(0.8 + jω·1 ms): passive and causal as read, yet Im y < 0 at the lowest frequencies
  // like the other convention's porous layer; the passive bounds of the two readings (a few 1e-3 % as read, where
  // the hats interpolate Re y exactly enough, against tens of % conjugated) say the convention is right.
  c.push_back({"mass-like passive wall (Im y < 0 at low frequency) without --time-convention", "mass_like.csv",
               "f,Re(y),Im(y)\n" + table(r, ",", [&](auto i) {
                 return parts(1.0 / std::complex<double>(0.8, 2.0 * M_PI * r.f[i] * 1e-3));
               }),
               {}, "",
               "so the convention is probably right and the surface mass-like at low frequency or its phase off (a "
               "calibration or reference-plane error): give --time-convention +jwt to fit them as read"});
  c.push_back({"absorption only, with header", "alpha.csv",
               "Frequency [Hz];Absorption coefficient\n" + table(r, ";", alpha, "\n", true), {}, "",
               "fixes the magnitude of the reflection factor R at each frequency but not its phase"});
  c.push_back({"absorption only, two bare columns", "alpha.txt", table(r, " ", alpha), {}, "",
               "alpha alone cannot be fitted"});
  c.push_back({"blank-separated with decimal commas", "german.txt",
               "# Messung 12.3.2024\n" + table(r, "   ", [&](auto i) { return parts(r.y[i]); }, "\n", true), {}, "", ""});
  c.push_back({"eight columns, chosen by header name", "eight.csv",
               "f_Hz,Re_R,Im_R,Re_z,Im_z,Re_y,Im_y,alpha\n" + table(r, ",", [&](auto i) {
                 auto p = parts(refl(i)), q = parts(z(i)), s = parts(r.y[i]);
                 return std::vector<std::string>{p[0], p[1], q[0], q[1], s[0], s[1], alpha(i)[0]};
               }),
               opts([](ReadOptions& o) { o.columns = ColumnMap::parse("f=F [Hz],re=RE_Y,im=im y"); }),
               "--columns 'f=F [Hz],re=RE_Y,im=im y'", ""});
  c.push_back({"frequency in kHz", "khz.csv",
               "f [kHz],Re(y),Im(y)\n" + [&] {
                 std::string out;
                 for (Eigen::Index i = 0; i < r.f.size(); ++i)  // exact: kHz values are written from f/1000 and
                   out += fmt::format("{:.17g},{},{}\n", r.f[i] / 1000.0, g17(r.y[i].real()), g17(r.y[i].imag()));
                 return out;  // re-multiplied by 1000, which restores f within 1 ulp
               }(),
               {}, "", ""});
  c.push_back({"numeric date line in the preamble, --skip-rows", "skip.csv",
               "12;3;2024\nTube B;100 mm\nFrequency;Re(y);Im(y)\n" +
                   table(r, ";", [&](auto i) { return parts(r.y[i]); }, "\n", true),
               opts([](ReadOptions& o) { o.format.skip_rows = 1; }), "--skip-rows 1", ""});
  c.push_back({"sign error in an export: Re y negated", "re_negated.csv",
               table(r, ",", [&](auto i) { return parts(std::complex<double>(-r.y[i].real(), r.y[i].imag())); }), {}, "",
               "a passive surface absorbs (Re y >= 0, in either time convention)"});
  c.push_back({"|R| in dB without a unit", "r_db_no_unit.csv", table(r, ",", mag_db_deg),
               polar_reflection(PhaseUnit::degrees),
               "--columns f,mag,phase --quantity reflection --phase-unit deg", "if the column is in dB, give --magnitude db"});
  c.push_back({"phase in degrees read as radians", "r_deg_as_rad.csv",
               table(r, ",", [&](auto i) { return std::vector<std::string>{g17(std::abs(refl(i))), mag_db_deg(i)[1]}; }),
               polar_reflection(PhaseUnit::radians),
               "--columns f,mag,phase --quantity reflection --phase-unit rad",
               "if the column is in degrees, give --phase-unit deg"});
  return c;
}

}  // namespace admitgen::test

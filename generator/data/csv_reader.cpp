// SPDX-License-Identifier: MIT
#include "data/csv_reader.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "core/sha256.hpp"
#include "data/column_selection.hpp"
#include "data/plausibility.hpp"
#include "data/text_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

namespace admitgen {
namespace {

constexpr double kPi = 3.141592653589793;

struct Row {
  long line;
  double f;
  std::complex<double> value;  ///< as in the file, after magnitude/phase conversion
};

constexpr const char* kSmallerFile = "keep the band you fit (and every second row if need be) in a smaller file";

/// The file's text, at most kMaxDataFileBytes and kMaxDataFileLines (csv_reader.hpp).
std::string read_text(const std::string& path) {
  const std::string text = read_bounded(path, kMaxDataFileBytes, "data file", kSmallerFile);
  const auto lines = std::count(text.begin(), text.end(), '\n');
  if (lines > kMaxDataFileLines)
    throw FileError(path, kMaxDataFileLines + 1,
                    fmt::format("more than {} lines, the most admitgen reads ({} here): {}", kMaxDataFileLines, lines,
                                kSmallerFile));
  return text;
}

/// How the two value columns turn into a complex number: scale of the magnitude, unit of the phase.
struct ValueUnits {
  MagnitudeScale magnitude = MagnitudeScale::linear;
  PhaseUnit phase = PhaseUnit::radians;
};

/// An option given on the command line wins; a unit in the file that contradicts it is an error.
ValueUnits value_units(const std::string& path, const ColumnSelection& s, const ReadOptions& o) {
  ValueUnits u;
  if (!s.polar) return u;
  const bool file_db = s.first_unit == UnitKind::decibel;
  if (o.magnitude && file_db && *o.magnitude != MagnitudeScale::decibel)
    throw FileError(path, 0, setting("magnitude") + " linear, but the file gives the magnitude in dB");
  u.magnitude = o.magnitude.value_or(file_db ? MagnitudeScale::decibel : MagnitudeScale::linear);
  const bool file_deg = s.second_unit == UnitKind::degrees, file_rad = s.second_unit == UnitKind::radians;
  if (o.phase && ((file_deg && *o.phase != PhaseUnit::degrees) || (file_rad && *o.phase != PhaseUnit::radians)))
    throw FileError(path, 0, fmt::format("{} {}, but the file gives the phase in {}", setting("phase"),
                                         *o.phase == PhaseUnit::degrees ? "deg" : "rad", file_deg ? "degrees" : "radians"));
  if (!o.phase && !file_deg && !file_rad)
    throw FileError(path, 0, fmt::format("the unit of the phase column is not stated in the file: give {} deg or {} rad", setting("phase"), setting("phase")));
  u.phase = o.phase.value_or(file_deg ? PhaseUnit::degrees : PhaseUnit::radians);
  return u;
}

/// The file's units against --rho-c: SI units in the header need it, a name that says normalised
/// (Z/Z0, "ratio") refuses it.
void check_scale_units(const std::string& path, const ColumnSelection& s, const ReadOptions& o) {
  const bool si = s.first_unit == UnitKind::si_impedance || s.first_unit == UnitKind::si_admittance ||
                  s.second_unit == UnitKind::si_impedance || s.second_unit == UnitKind::si_admittance;
  if (si && !o.rho_c)
    throw FileError(path, 0, fmt::format("the file gives the {} in SI units (Pa s/m or m/(Pa s)): give {} RHO_C "
                                         "(rho0*c0 of the air in the tube in Pa s/m, {} at 20 C)",
                                         quantity_name(s.quantity), setting("rho_c"), kTypicalRhoC));
  if (o.rho_c && s.named_normalised && !si)
    throw FileError(path, 0, fmt::format("{} given, but the column names say the values are normalised (Z/Z0, ratio): drop {}", setting("rho_c"), setting("rho_c")));
}

std::vector<Row> parse_rows(const std::string& path, const TextTable& t, const ColumnSelection& s, const ValueUnits& u) {
  std::vector<Row> rows;
  const double f_scale = s.f_unit == UnitKind::kilohertz ? 1000.0 : 1.0;
  for (const TextLine& line : t.rows) {
    if (line.fields.size() != s.width)
      throw FileError(path, line.number,
                      fmt::format("expected {} columns, found {} ({}; set {} to describe the file{})", s.width,
                                  line.fields.size(), t.describe(), setting("columns"),
                                  t.header ? ", the header names " + fmt::format("{} columns", t.header->fields.size()) : ""),
                      fmt::format("{}", fmt::join(line.fields, std::string(1, t.delimiter == '\t' ? ' ' : t.delimiter))));
    const auto number_at = [&](std::size_t index, const char* role) {
      const auto& field = line.fields[index];
      const auto value = parse_field(t, field);
      if (!value) throw FileError(path, line.number, fmt::format("column {} ({}) is not a number", index + 1, role), field);
      if (!std::isfinite(*value))
        throw FileError(path, line.number, fmt::format("column {} ({}) is not finite", index + 1, role), field);
      return *value;
    };
    const double f = number_at(s.f, "f") * f_scale;
    if (!(f > 0.0)) throw FileError(path, line.number, "frequency must be positive (Hz)", line.fields[s.f]);
    const double a = number_at(s.first, s.polar ? "mag" : "re"), b = number_at(s.second, s.polar ? "phase" : "im");
    if (!s.polar) {
      rows.push_back({line.number, f, {a, b}});
      continue;
    }
    if (u.magnitude == MagnitudeScale::linear && a < 0.0)
      throw FileError(path, line.number, "negative magnitude: if the column is in dB, give " + setting("magnitude") + " db", line.fields[s.first]);
    if (u.phase == PhaseUnit::radians && std::abs(b) > 2.0 * kPi * (1.0 + 1e-9))
      throw FileError(path, line.number, "phase beyond 2 pi read in radians: if the column is in degrees, give " + setting("phase") + " deg",
                      line.fields[s.second]);
    const double mag = u.magnitude == MagnitudeScale::decibel ? std::pow(10.0, a / 20.0) : a;  // 20 log10 |x|
    rows.push_back({line.number, f, std::polar(mag, u.phase == PhaseUnit::degrees ? b * kPi / 180.0 : b)});
  }
  return rows;
}

/// Sorts by frequency (stable, with a warning) and rejects duplicates naming both lines.
void sort_and_check(const std::string& path, std::vector<Row>& rows, std::vector<std::string>& warnings) {
  const auto by_f = [](const Row& a, const Row& b) { return a.f < b.f; };
  if (!std::is_sorted(rows.begin(), rows.end(), by_f)) {
    std::stable_sort(rows.begin(), rows.end(), by_f);
    warnings.push_back(fmt::format("{}: rows were not in ascending frequency order; sorted", path));
  }
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i].f == rows[i - 1].f)
      throw FileError(path, std::max(rows[i].line, rows[i - 1].line),
                      fmt::format("duplicate frequency (also on line {})", std::min(rows[i].line, rows[i - 1].line)),
                      fmt::format("{}", rows[i].f));
}

/// Normalised admittance in e^{+jωt} from a file value already in e^{+jωt}.
std::complex<double> to_admittance(const std::string& path, const Row& row, Quantity q, const ReadOptions& opt) {
  const std::complex<double> v = row.value;
  const double rc = opt.rho_c.value_or(1.0);
  switch (q) {
    case Quantity::admittance:
      return v * rc;  // SI admittance [m/(Pa s)] times ρ0c0 gives the normalised one
    case Quantity::impedance:
      if (v == 0.0) throw FileError(path, row.line, "impedance is zero: admittance undefined", "0");
      return rc / v;
    case Quantity::reflection:
      if (v == -1.0) throw FileError(path, row.line, "reflection factor is -1: admittance undefined", "-1");
      return (1.0 - v) / (1.0 + v);
  }
  throw InternalError("unhandled Quantity");
}

void keep_band(const std::string& path, std::vector<Row>& rows, const std::optional<Band>& band) {
  if (!band) return;
  rows.erase(std::remove_if(rows.begin(), rows.end(), [&](const Row& r) { return r.f < band->lo_hz || r.f > band->hi_hz; }),
             rows.end());
  if (rows.empty()) throw FileError(path, 0, fmt::format("no data inside {} {}:{} Hz", setting("band"), band->lo_hz, band->hi_hz));
}

void check_options(const ReadOptions& options) {
  if (options.quantity == Quantity::reflection && options.rho_c)
    throw InputError(setting("rho_c") + " does not apply to a reflection factor (it is dimensionless)");
  if (options.rho_c && !(*options.rho_c > 0.0 && std::isfinite(*options.rho_c)))
    throw InputError(fmt::format("{} must be a positive number, got {}", setting("rho_c"), *options.rho_c));
  if (options.format.skip_rows < 0) throw InputError(setting("format.skip_rows") + " must not be negative");
}

}  // namespace

Measurement read_measurement(const std::string& path, const ReadOptions& options) {
  check_options(options);
  const std::string text = read_text(path);
  Measurement m;
  m.path = path;
  m.sha256 = sha256_hex(text);
  const TextTable table = split_table(path, text, options.format);
  const ColumnSelection cols = select_columns(path, table, options);
  if (cols.quantity == Quantity::reflection && options.rho_c)
    throw InputError(setting("rho_c") + " does not apply to a reflection factor (it is dimensionless)");
  check_scale_units(path, cols, options);
  auto rows = parse_rows(path, table, cols, value_units(path, cols, options));
  sort_and_check(path, rows, m.warnings);
  keep_band(path, rows, options.band);
  if (static_cast<int>(rows.size()) < kMinimumPoints)
    throw FileError(path, 0, fmt::format("only {} data point(s); at least {} are needed", rows.size(), kMinimumPoints));
  const bool conjugate = options.time_convention == TimeConvention::minus_jwt;  // e^{−jωt} → e^{+jωt}
  const auto n = static_cast<Eigen::Index>(rows.size());
  m.f_hz.resize(n);
  m.y.resize(n);
  Eigen::ArrayXcd values(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    auto& r = rows[static_cast<std::size_t>(i)];
    if (conjugate) r.value = std::conj(r.value);
    m.f_hz[i] = r.f;
    values[i] = r.value;
    m.y[i] = to_admittance(path, r, cols.quantity, options);
  }
  if (rows.back().f < 20.0)
    throw FileError(path, rows.back().line, "all frequencies are below 20 Hz: expected Hz (not kHz)",
                    fmt::format("{}", rows.back().f));
  check_plausibility({path, m.f_hz, values, m.y, cols.quantity, options}, m.warnings);
  m.quantity = quantity_name(cols.quantity);
  m.read_as = fmt::format("{}; {}; {}, e^{{{}jwt}}", table.describe(), cols.describe,
                          options.rho_c ? fmt::format("SI, rho0*c0 = {:g} Pa s/m", *options.rho_c) : "normalised",
                          conjugate ? "-" : "+");
  return m;
}

}  // namespace admitgen

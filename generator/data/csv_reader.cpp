#include "data/csv_reader.hpp"

#include "core/errors.hpp"
#include "core/sha256.hpp"
#include "data/number_parsing.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numeric>
#include <sstream>

namespace admitgen {
namespace {

struct Row {
  long line;
  double f, re, im;
};

/// Fields are separated by ',' (surrounding blanks trimmed, so an empty field is kept and reported)
/// or, on lines without a comma, by runs of blanks.
std::vector<std::string> tokenize(const std::string& line) {
  std::vector<std::string> fields;
  const bool commas = line.find(',') != std::string::npos;
  std::string current;
  const auto flush = [&] {
    const auto b = current.find_first_not_of(" \t");
    const auto e = current.find_last_not_of(" \t");
    fields.push_back(b == std::string::npos ? std::string() : current.substr(b, e - b + 1));
    current.clear();
  };
  for (char c : line) {
    if (commas ? c == ',' : (c == ' ' || c == '\t')) {
      if (commas || !current.empty()) flush();
    } else {
      current += c;
    }
  }
  if (commas || !current.empty()) flush();
  return fields;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, 0, "cannot open data file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // UTF-8 BOM
  return text;
}

bool all_non_numeric(const std::vector<std::string>& fields) {
  return std::none_of(fields.begin(), fields.end(),
                      [](const std::string& s) { return parse_double(s).has_value(); });
}

std::vector<Row> parse_rows(const std::string& path, const std::string& text, const ColumnMap& cols) {
  std::vector<Row> rows;
  std::istringstream in(text);
  std::string line;
  long number = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const auto fields = tokenize(line);
    if (header_allowed && all_non_numeric(fields)) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (static_cast<int>(fields.size()) != cols.count)
      throw FileError(path, number,
                      fmt::format("expected {} columns, found {} (set --columns to describe the file)",
                                  cols.count, fields.size()),
                      line);
    const auto number_at = [&](int index, const char* role) {
      const auto& field = fields[static_cast<std::size_t>(index)];
      const auto value = parse_double(field);
      if (!value) throw FileError(path, number, fmt::format("column {} ({}) is not a number", index + 1, role), field);
      if (!std::isfinite(*value))
        throw FileError(path, number, fmt::format("column {} ({}) is not finite", index + 1, role), field);
      return *value;
    };
    Row row{number, number_at(cols.f, "f"), number_at(cols.re, "re"), number_at(cols.im, "im")};
    if (!(row.f > 0.0))
      throw FileError(path, number, "frequency must be positive (Hz)", fields[static_cast<std::size_t>(cols.f)]);
    rows.push_back(row);
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

std::complex<double> to_admittance(const std::string& path, const Row& row, const ReadOptions& opt) {
  const std::complex<double> v(row.re, row.im);
  const double rc = opt.rho_c.value_or(1.0);
  switch (opt.quantity) {
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

/// Normalised admittance of real surfaces lies well below 50 in magnitude (a rigid wall is 0, air
/// itself 1); values far above mean SI units were read as normalised. Frequencies below 20 Hz
/// everywhere mean kHz (or rad/s confusion the other way is caught by the caller's band checks).
void check_units(const std::string& path, const std::vector<Row>& rows, const Eigen::ArrayXcd& y,
                 const ReadOptions& opt) {
  Eigen::ArrayXd mag = y.abs();
  std::vector<double> sorted(mag.data(), mag.data() + mag.size());
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  if (median > 50.0)
    throw FileError(path, 0,
                    fmt::format("median |normalised admittance| is {:.4g}: the values look like SI units or the "
                                "wrong quantity; use --rho-c VALUE for SI data or check --quantity",
                                median));
  if (opt.rho_c && median < 1e-6)
    throw FileError(path, 0, fmt::format("median |normalised admittance| is {:.4g} after dividing by --rho-c: "
                                         "the data look already normalised (drop --rho-c)", median));
  if (rows.back().f < 20.0)
    throw FileError(path, rows.back().line, "all frequencies are below 20 Hz: expected Hz (not kHz)",
                    fmt::format("{}", rows.back().f));
}

}  // namespace

Measurement read_measurement(const std::string& path, const ReadOptions& options) {
  if (options.quantity == Quantity::reflection && options.rho_c)
    throw InputError("--rho-c does not apply to a reflection factor (it is dimensionless)");
  if (options.rho_c && !(*options.rho_c > 0.0 && std::isfinite(*options.rho_c)))
    throw InputError(fmt::format("--rho-c must be a positive number, got {}", *options.rho_c));
  const std::string text = read_text(path);
  Measurement m;
  m.path = path;
  m.sha256 = sha256_hex(text);
  auto rows = parse_rows(path, text, options.columns);
  if (rows.empty()) throw FileError(path, 0, "no data rows");
  sort_and_check(path, rows, m.warnings);
  if (options.band) {
    const Band b = *options.band;
    rows.erase(std::remove_if(rows.begin(), rows.end(), [&](const Row& r) { return r.f < b.lo_hz || r.f > b.hi_hz; }),
               rows.end());
    if (rows.empty())
      throw FileError(path, 0, fmt::format("no data inside --band {}:{} Hz", b.lo_hz, b.hi_hz));
  }
  if (static_cast<int>(rows.size()) < kMinimumPoints)
    throw FileError(path, 0, fmt::format("only {} data point(s); at least {} are needed", rows.size(), kMinimumPoints));
  const auto n = static_cast<Eigen::Index>(rows.size());
  m.f_hz.resize(n);
  m.y.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& r = rows[static_cast<std::size_t>(i)];
    m.f_hz[i] = r.f;
    m.y[i] = to_admittance(path, r, options);
  }
  check_units(path, rows, m.y, options);
  return m;
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
// Reading measured data (docs/reading-data.md): formats, conversions, band selection.
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <string>

#include <unistd.h>

using namespace admitgen;
using admitgen::test::sample;
using admitgen::test::scratch_dir;
using admitgen::test::write_text;

namespace {
// Every doctest case runs as its own CTest process, in parallel with the others: one folder per process,
// made once (scratch_dir empties its folder, which must not remove another fixture of the same case).
std::string fixture(const std::string& name, const std::string& text) {
  static const std::string dir = scratch_dir("csv_reader_" + std::to_string(::getpid()));
  const std::string path = dir + "/" + name;
  write_text(path, text);
  return path;
}
// Conversions are one complex division: exact to a few ulp, so 1e-14 relative.
constexpr double kConversionTol = 1e-14;
}  // namespace

TEST_CASE("reader: comma, whitespace, BOM, CRLF, header and comments all read the same values") {
  const std::string rows = "100,0.1,0.2\n200,0.3,-0.4\n300,0.5,0.6\n";
  const auto plain = read_measurement(fixture("plain.csv", rows), ReadOptions{});
  const auto fancy = read_measurement(
      fixture("fancy.csv", "\xEF\xBB\xBF# comment\r\nf, re, im\r\n\r\n100 , 0.1, 0.2\r\n200,0.3,-0.4\r\n# mid\r\n300,0.5,0.6\r\n"),
      ReadOptions{});
  const auto spaces = read_measurement(fixture("spaces.txt", "100 0.1 0.2\n200\t0.3 -0.4\n  300  0.5  0.6\n"), ReadOptions{});
  for (const auto* m : {&fancy, &spaces}) {
    REQUIRE(m->size() == 3);
    CHECK((m->f_hz - plain.f_hz).abs().maxCoeff() == 0.0);
    CHECK((m->y - plain.y).abs().maxCoeff() == 0.0);
  }
  CHECK(plain.y[1] == std::complex<double>(0.3, -0.4));
  CHECK(plain.sha256.size() == 64);
}

TEST_CASE("reader: unsorted rows are sorted with a warning") {
  const auto m = read_measurement(fixture("unsorted.csv", "300,3,0\n100,1,0\n200,2,0\n"), ReadOptions{});
  CHECK(m.f_hz[0] == 100.0);
  CHECK(m.y[2].real() == 3.0);
  REQUIRE(m.warnings.size() == 1);
  CHECK(m.warnings[0].find("sorted") != std::string::npos);
}

TEST_CASE("reader: impedance, reflection and SI conversions give the same admittance") {
  const std::complex<double> y(0.2, 0.11), z = 1.0 / y, r = (1.0 - y) / (1.0 + y);
  const double rc = 413.3;
  const auto line = [](double f, std::complex<double> v) { return fmt::format("{},{:.17g},{:.17g}\n", f, v.real(), v.imag()); };
  const auto file = [&](const char* name, std::complex<double> v) {
    return fixture(name, line(100, v) + line(200, v) + line(300, v));
  };
  ReadOptions opt;
  opt.quantity = Quantity::impedance;
  const auto from_z = read_measurement(file("z.csv", z), opt);
  opt.quantity = Quantity::reflection;
  const auto from_r = read_measurement(file("r.csv", r), opt);
  opt.quantity = Quantity::impedance;
  opt.rho_c = rc;
  const auto from_z_si = read_measurement(file("zsi.csv", z * rc), opt);
  opt.quantity = Quantity::admittance;
  const auto from_y_si = read_measurement(file("ysi.csv", y / rc), opt);
  for (const auto* m : {&from_z, &from_r, &from_z_si, &from_y_si}) CHECK(std::abs(m->y[0] - y) <= kConversionTol * std::abs(y) * 8);
}

TEST_CASE("reader: column selection and band selection on the shared Basotect format") {
  ReadOptions opt;
  opt.columns = ColumnMap::parse("f,_,_,_,_,re,im,_");
  const auto all = read_measurement(sample("basotect_tuberlin/rect_5cm.csv"), opt);
  CHECK(all.size() == 904);
  CHECK(all.f_hz[0] == doctest::Approx(203.125).epsilon(1e-15));
  CHECK(all.y[0].real() == doctest::Approx(0.071897472).epsilon(1e-15));  // Re_y column of the first row
  opt.band = Band::parse("500:1000");
  const auto band = read_measurement(sample("basotect_tuberlin/rect_5cm.csv"), opt);
  CHECK(band.f_hz.minCoeff() >= 500.0);
  CHECK(band.f_hz.maxCoeff() <= 1000.0);
  CHECK(band.size() == 321);  // 1.5625 Hz steps from 203.125: 500.0 .. 1000.0 inclusive
  // The stored absorption column agrees with 1 − |R|² from the admittance column (file rounding 1e-7).
  const Eigen::ArrayXd alpha = absorption(all.y);
  ReadOptions alpha_col;
  alpha_col.columns = ColumnMap::parse("f,_,_,_,_,_,re,im");  // any two numeric columns: reuse Im_y, alpha
  alpha_col.plausibility_errors = false;  // two real columns, not an admittance
  const auto stored = read_measurement(sample("basotect_tuberlin/rect_5cm.csv"), alpha_col);
  CHECK((alpha - stored.y.imag()).abs().maxCoeff() < 2e-6);
}

TEST_CASE("reader: option parsers reject malformed specs") {
  CHECK_THROWS_AS(ColumnMap::parse("f,re"), InputError);
  CHECK_THROWS_AS(ColumnMap::parse("f,re,im,f"), InputError);
  CHECK_THROWS_AS(ColumnMap::parse("f,re,imag"), InputError);
  CHECK_THROWS_AS(Band::parse("1000:500"), InputError);
  CHECK_THROWS_AS(Band::parse("abc"), InputError);
  CHECK_THROWS_AS(Band::parse("-5:100"), InputError);
  CHECK_THROWS_AS(parse_quantity("pressure"), InputError);
  const Band b = Band::parse("200:1600");
  CHECK(b.lo_hz == 200.0);
  CHECK(b.hi_hz == 1600.0);
}

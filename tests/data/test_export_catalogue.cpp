// SPDX-License-Identifier: MIT
// The export catalogue (tests/data/export_catalogue.hpp) read in-process: every entry reads to the
// reference admittance of the plain file, or fails with its documented message (as the CLI prints it:
// the settings the library names spelled as flags).
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "data/export_catalogue.hpp"
#include "test_support.hpp"

#include <doctest/doctest.h>

#include <limits>

using namespace admitgen;
using admitgen::test::Export;
using admitgen::test::Reference;

namespace {

/// Tolerance from the arithmetic. A value written with 17 significant digits parses back to the same
/// double, so the only errors are the roundings of the conversions: the test forms v = f(y) (at most
/// kOps = 12 correctly rounded operations, complex division and log10/pow/sin/cos included, each
/// ≤ 2 ulp relative) and the reader inverts it with as many. An error δ in v becomes κ·δ in y, with
/// κ = |v/y|·|dy/dv| the condition number of the inverse map: 1 for y·ρc and ρc/v, |2R/((1−R)(1+R))|
/// for R → y, and |ln 10/20 · 20 log10|R|| more for a dB magnitude (dB → |R| multiplies the absolute
/// dB error). So |Δy|/|y| ≤ 2·kOps·2ε·κmax; with κmax measured on the reference below (< 10) that is
/// < 1e-12, the bound the catalogue asserts.
constexpr double kOps = 12.0;
constexpr double kTolerance = 1e-12;

double worst_condition(const Reference& r) {
  double kappa = 1.0;
  for (Eigen::Index i = 0; i < r.y.size(); ++i) {
    const std::complex<double> R = (1.0 - r.y[i]) / (1.0 + r.y[i]);
    const double k_refl = std::abs(2.0 * R / ((1.0 - R) * (1.0 + R)));
    const double k_db = std::log(10.0) / 20.0 * std::abs(20.0 * std::log10(std::abs(R)));
    kappa = std::max({kappa, k_refl * (1.0 + k_db), k_refl * (1.0 + std::abs(std::arg(R)))});
  }
  return kappa;
}

/// Writes an export into `dir` (each test case has its own: CTest runs cases as parallel processes).
std::string write_export(const std::string& dir, const Export& e) {
  const std::string path = dir + "/" + e.file;
  test::write_text(path, e.text);
  return path;
}

}  // namespace

TEST_CASE("export catalogue: every realistic export reads to the reference admittance or fails as documented") {
  const Reference r;
  const double kappa = worst_condition(r);
  INFO("worst condition number of an inverse conversion: ", kappa);
  REQUIRE(2.0 * kOps * 2.0 * std::numeric_limits<double>::epsilon() * kappa < kTolerance);
  const auto catalogue = test::export_catalogue(r);
  CHECK(catalogue.size() >= 15);
  const std::string dir = test::scratch_dir("export_catalogue_reader");
  int reads = 0, errors = 0;
  for (const Export& e : catalogue) {
    INFO(std::string(e.name));
    const std::string path = write_export(dir, e);
    if (e.error.empty()) {
      const Measurement m = read_measurement(path, e.options);
      INFO(m.read_as);
      REQUIRE(m.size() == r.f.size());
      CHECK(((m.f_hz - r.f).abs() / r.f).maxCoeff() <= 4.0 * std::numeric_limits<double>::epsilon());  // kHz: ×1000
      CHECK(((m.y - r.y).abs() / r.y.abs()).maxCoeff() < kTolerance);
      CHECK(m.warnings.empty());
      ++reads;
    } else {
      std::string message;
      try {
        read_measurement(path, e.options);
      } catch (const InputError& error) {
        message = error.spelled(cli::flag_for);
      }
      INFO(message);
      CHECK(message.find(e.error) != std::string::npos);
      CHECK(message.find(path) == 0);  // names the file
      ++errors;
    }
  }
  CHECK(reads >= 10);
  CHECK(errors >= 6);
}

TEST_CASE("export catalogue: the reference itself reads exactly (17 digits round-trip)") {
  const Reference r;
  const auto catalogue = test::export_catalogue(r);
  const std::string dir = test::scratch_dir("export_catalogue_round_trip");
  const Measurement plain = read_measurement(write_export(dir, catalogue.front()), catalogue.front().options);
  CHECK((plain.f_hz - r.f).abs().maxCoeff() == 0.0);
  CHECK((plain.y - r.y).abs().maxCoeff() == 0.0);
  CHECK(plain.quantity == "admittance");
}

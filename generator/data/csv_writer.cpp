// SPDX-License-Identifier: MIT
#include "data/csv_writer.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"

#include <fmt/format.h>

namespace admitgen {

std::string format_admittance_csv(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y, const CsvProvenance& provenance) {
  ADMITGEN_ENSURE(f_hz.size() == y.size(), "{} frequencies but {} values", f_hz.size(), y.size());
  std::string out = fmt::format("# admitgen {} synthetic data\n", kVersion);
  for (const auto& [key, value] : provenance) {
    ADMITGEN_ENSURE(value.find_first_of("\r\n") == std::string::npos, "provenance '{}' spans lines", key);
    out += fmt::format("# {}: {}\n", key, value);
  }
  out += "# columns: frequency [Hz], Re y, Im y (y = normalised surface admittance, e^{+jwt})\n";
  out += "f_hz,re_y,im_y\n";
  for (Eigen::Index i = 0; i < f_hz.size(); ++i)
    out += fmt::format("{:.17g},{:.17g},{:.17g}\n", f_hz[i], y[i].real(), y[i].imag());
  return out;
}

void write_admittance_csv(const std::string& path, const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y,
                          const CsvProvenance& provenance) {
  write_file_atomically(path, format_admittance_csv(f_hz, y, provenance));
}

}  // namespace admitgen

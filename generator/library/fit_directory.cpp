// SPDX-License-Identifier: MIT
#include "library/fit_directory.hpp"

#include "core/atomic_file.hpp"
#include "io/fit_file.hpp"
#include "io/posterior_export.hpp"
#include "report/fit_report.hpp"
#include "selection/fit_record.hpp"

#include <filesystem>

namespace admitgen::library {

FitRecord write_fit_directory(const std::string& dir, const Measurement& data, const ReadOptions& read,
                              const FitSettings& settings, const FitResult& fit) {
  FitRecord record = fit_record(data, read, settings, fit);
  record.posterior = write_posterior_export(dir, data, settings, fit);  // samples, covariance, bands as CSV
  write_file_atomically((std::filesystem::path(dir) / "fit.json").string(), io::fit_text(record));
  report::write_fit_report(dir, record, data);
  return record;
}

}  // namespace admitgen::library

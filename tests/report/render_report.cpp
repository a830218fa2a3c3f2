// SPDX-License-Identifier: MIT
// Test tool: renders a report page from saved JSON, for the headless-browser test and docs/reports.md
// screenshots. Usage:
//   admitgen_render_report diagnosis DIAGNOSIS.json OUT_DIR      writes OUT_DIR/diagnosis.html
//   admitgen_render_report fit FIT.json DATA.csv OUT_DIR          writes OUT_DIR/report.html (data read as f,re,im)
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "data/csv_reader.hpp"
#include "report/diagnosis_report.hpp"
#include "report/fit_report.hpp"

#include <fmt/core.h>

#include <fstream>
#include <string>

namespace {

nlohmann::ordered_json read_json(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw admitgen::FileError(path, 0, "cannot read");
  return nlohmann::ordered_json::parse(in);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string kind = argc > 1 ? argv[1] : "";
    if (kind == "diagnosis" && argc == 4) {
      admitgen::ensure_writable_directory(argv[3]);
      fmt::print("{}\n", admitgen::report::write_diagnosis_report(argv[3], read_json(argv[2])));
      return 0;
    }
    if (kind == "fit" && argc == 5) {
      admitgen::ensure_writable_directory(argv[4]);
      const auto data = admitgen::read_measurement(argv[3], admitgen::ReadOptions{});
      fmt::print("{}\n", admitgen::report::write_fit_report(argv[4], read_json(argv[2]), data));
      return 0;
    }
    fmt::print(stderr, "usage: {0} diagnosis DIAGNOSIS.json OUT_DIR | {0} fit FIT.json DATA.csv OUT_DIR\n", argv[0]);
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 2;
  }
}

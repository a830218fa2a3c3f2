// SPDX-License-Identifier: MIT
#include "checks/report.hpp"

namespace admitgen::checks {

void CheckResult::fail(std::string what) {
  status = Status::fail;
  failures.push_back(std::move(what));
}

CheckResult CheckResult::not_applicable(std::string why) {
  status = Status::not_applicable;
  summary = std::move(why);
  return *this;
}

const char* band_place_text(BandPlace place) {
  switch (place) {
    case BandPlace::data_band_unknown: return "data band unknown";
    case BandPlace::below: return "below the data band";
    case BandPlace::above: return "above the data band";
    case BandPlace::inside: return "inside the data band";
    case BandPlace::overlapping: return "overlapping the data band";
  }
  return "?";
}

bool CheckReport::passed() const { return failed_checks().empty(); }

std::vector<std::string> CheckReport::failed_checks() const {
  std::vector<std::string> names;
  for (const auto& c : checks)
    if (c.status == Status::fail) names.push_back(c.name);
  return names;
}

}  // namespace admitgen::checks

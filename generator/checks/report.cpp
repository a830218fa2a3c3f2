// SPDX-License-Identifier: MIT
#include "checks/report.hpp"

#include <fmt/format.h>

namespace admitgen::checks {

void CheckResult::fail(std::string what) {
  status = Status::fail;
  failures.push_back(std::move(what));
}

const char* status_name(Status status) {
  switch (status) {
    case Status::pass: return "pass";
    case Status::fail: return "FAIL";
    case Status::not_applicable: return "n/a";
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

nlohmann::ordered_json CheckReport::to_json() const {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& c : checks)
    list.push_back({{"check", c.name},
                    {"status", c.status == Status::fail ? "fail" : status_name(c.status)},
                    {"method", c.method},
                    {"summary", c.summary},
                    {"failures", c.failures},
                    {"details", c.details}});
  return {{"schema", "admitgen.check/1"}, {"subject", subject}, {"kind", kind},
          {"passed", passed()}, {"failed", failed_checks()}, {"checks", list}};
}

std::string CheckReport::to_text() const {
  std::string s = fmt::format("admitgen check {} ({})\n", subject, kind);
  for (const auto& c : checks) {
    s += fmt::format("  {:<4} {:<22} {}\n", status_name(c.status), c.name, c.summary);
    for (const auto& f : c.failures) s += fmt::format("         - {}\n", f);
  }
  const auto failed = failed_checks();
  s += failed.empty() ? "all checks passed\n" : fmt::format("{} check(s) failed\n", failed.size());
  return s;
}

}  // namespace admitgen::checks

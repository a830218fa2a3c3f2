// SPDX-License-Identifier: MIT
/// @file
/// The result of `admitgen check`: one entry per check, each failure named with where it is, the figures
/// that decided it, rendered as text or as JSON (schema "admitgen.check/1").
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace admitgen::checks {

enum class Status { pass, fail, not_applicable };

struct CheckResult {
  std::string name;     ///< stable identifier: causality, discrete_stability, passivity_continuous, ...
  std::string method;   ///< how it was decided
  Status status = Status::pass;
  std::string summary;  ///< one line with the deciding figure (margin, minimum of Re G, ...)
  std::vector<std::string> failures;  ///< each names the failure and where it is
  nlohmann::ordered_json details = nlohmann::ordered_json::object();

  /// Records a failure (and marks the check failed).
  void fail(std::string what);
};

struct CheckReport {
  std::string subject;  ///< the file checked
  std::string kind;     ///< "header" or "fit"
  std::vector<CheckResult> checks;

  bool passed() const;
  /// Names of the failed checks, in order.
  std::vector<std::string> failed_checks() const;
  nlohmann::ordered_json to_json() const;
  std::string to_text() const;
};

const char* status_name(Status status);

}  // namespace admitgen::checks

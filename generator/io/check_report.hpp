// SPDX-License-Identifier: MIT
/// @file
/// The check report as `admitgen check` prints it (docs/formats.md, "check report"; docs/cli.md): the one
/// writer of its text and of its JSON (schema "admitgen.check/1"). It owns the keys, their order and how
/// each check's typed figures (checks/report.hpp) are spelled.
#pragma once

#include "checks/report.hpp"

#include <string>

namespace admitgen::io {

/// The report as JSON indented by 2, then a newline.
std::string check_report_json(const checks::CheckReport& report);

/// The report as text: a line per check (status, name, summary), its failures indented below it, and a
/// closing line ("all checks passed" or how many failed).
std::string check_report_text(const checks::CheckReport& report);

}  // namespace admitgen::io

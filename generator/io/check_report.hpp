// SPDX-License-Identifier: MIT
/// @file
/// The check report as `admitgen check` prints it (docs/formats.md, "check report"; docs/cli.md): the one
/// writer of its text and of its JSON (schema "admitgen.check/1"). It owns the keys, their order and how
/// each check's typed figures (checks/report.hpp) are spelled, in one field list per record
/// (io/record_fields.hpp).
#pragma once

#include "checks/report.hpp"
#include "io/key_table.hpp"

#include <string>
#include <utility>
#include <vector>

namespace admitgen::io {

/// The report as JSON indented by 2, then a newline.
std::string check_report_json(const checks::CheckReport& report);

/// The report as text: a line per check (status, name, summary), its failures indented below it, and a
/// closing line ("all checks passed" or how many failed).
std::string check_report_text(const checks::CheckReport& report);

/// The keys of the JSON report as its field lists name them (the table of docs/formats.md, "check report"),
/// and those of each check's `details` by the check's name.
std::vector<KeyNode> check_report_keys();
std::vector<std::pair<std::string, std::vector<KeyNode>>> check_details_keys();

}  // namespace admitgen::io

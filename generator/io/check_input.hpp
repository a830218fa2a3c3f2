// SPDX-License-Identifier: MIT
/// @file
/// What `admitgen check` reads: a header written by `admitgen emit` or a fit.json, decided by content.
#pragma once

#include "checks/check_suite.hpp"

#include <string>

namespace admitgen::io {

/// The check subject of a header's text: its model block read by io::read_emitted_header (throws
/// InputError if it has no readable admitgen:model block) and the text itself.
checks::CheckSubject header_subject(const std::string& text, const std::string& origin);

/// Reads FILE.h or FIT.json (decided by content: JSON must be a fit, schema admitgen.fit/1, anything
/// else a header with a model block). Throws FileError if the file is unreadable or neither.
checks::CheckSubject load_check_subject(const std::string& path, const std::string& order = {},
                                        Estimate estimate = Estimate::passive);

}  // namespace admitgen::io

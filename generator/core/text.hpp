// SPDX-License-Identifier: MIT
/// @file
/// Small text helpers shared by the readers of data files, parameter lists and effect names.
#pragma once

#include <string_view>

namespace admitgen {

/// `text` without the leading and trailing characters found in `characters` (blanks and tabs by default).
std::string_view trim(std::string_view text, std::string_view characters = " \t");

}  // namespace admitgen

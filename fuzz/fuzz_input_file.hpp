/// @file
/// The readers under test take file paths (they name the file in their errors), so each fuzz input is
/// written to a scratch file first. One file per process, rewritten for every input; removed at exit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace admitgen::fuzz {

/// Writes `size` bytes to this process's scratch file (under $TMPDIR, default /tmp) and returns its
/// path; `suffix` is appended to the name (".csv", ".json", ...).
const std::string& write_input_file(const std::uint8_t* data, std::size_t size, const char* suffix);

}  // namespace admitgen::fuzz

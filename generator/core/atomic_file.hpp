// SPDX-License-Identifier: MIT
/// @file
/// Output files appear whole or not at all: content goes to a temporary beside the target and is
/// renamed over it (rename(2) is atomic within one file system).
#pragma once

#include <string>

namespace admitgen {

/// Writes `content` to `path` atomically. Throws InputError naming the path if it cannot be written.
void write_file_atomically(const std::string& path, const std::string& content);

/// Creates directory `dir` (and parents) if needed; throws InputError if that fails or it is not
/// writable, so that no work is done before a failure to write the result.
void ensure_writable_directory(const std::string& dir);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Reading a user's file whole, with a size limit: every reader of user files (data, fit.json, headers,
/// priors) goes through it, so a huge file, a device (/dev/zero) or a pipe cannot exhaust memory, and a
/// directory is named as such rather than read as empty.
#pragma once

#include <cstddef>
#include <string>

namespace admitgen {

/// The bytes of `path`. Throws FileError naming the file if it cannot be opened, is a directory, or holds
/// more than `max_bytes` (reading stops one block past the limit); `what` names the file's role in the
/// messages ("data file", "fit", ...); `advice`, if given, ends the too-large message.
std::string read_bounded(const std::string& path, std::size_t max_bytes, const char* what, const char* advice = nullptr);

/// The limit for JSON documents and headers that admitgen wrote (fit.json files are ~0.3 MB).
inline constexpr std::size_t kMaxDocumentBytes = std::size_t{64} << 20;

}  // namespace admitgen

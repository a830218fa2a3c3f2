// SPDX-License-Identifier: MIT
/// @file
/// SHA-256 of files and strings (OpenSSL libcrypto), lower-case hex; stamps every generated output.
#pragma once

#include <string>

namespace admitgen {

std::string sha256_hex(const std::string& bytes);
/// Hash of a file's bytes; throws InputError if it cannot be read.
std::string sha256_file_hex(const std::string& path);

}  // namespace admitgen

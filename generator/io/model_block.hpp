// SPDX-License-Identifier: MIT
/// @file
/// The emitted header's machine-readable block (docs/formats.md, "The header's machine-readable block"):
/// one line of JSON, schema "admitgen.emit/1", between "admitgen:model" and "admitgen:end", stating exactly
/// what the header emits. model_block is its one writer and read_emitted_header its one reader; the record
/// read is codegen::EmittedHeader, which `admitgen check` receives (checks/check_suite.hpp).
#pragma once

#include "codegen/emission.hpp"

#include <string>

namespace admitgen::io {

/// Schema identifier of a header's model block.
inline constexpr const char* kModelBlockSchema = "admitgen.emit/1";

/// The model block of `emission` (one line of JSON).
std::string model_block(const codegen::Emission& emission);

/// The header of `emission` from the template text, carrying its model block (codegen::render_header).
std::string header_text(const codegen::Emission& emission, const std::string& template_text,
                        const std::string& file_name);

/// What a header emitted, read back from its model block. Throws InputError naming `origin`, the key and
/// the value if the block is absent or unreadable, or if a fixed-point field lies outside the bounds the
/// runtime enforces at init.
codegen::EmittedHeader read_emitted_header(const std::string& header_text, const std::string& origin);

}  // namespace admitgen::io

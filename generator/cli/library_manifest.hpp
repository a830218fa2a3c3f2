// SPDX-License-Identifier: MIT
/// @file
/// The library manifest (docs/library.md, "Manifest"): a TOML file naming the library and its materials.
/// Every key of a material other than `name` and `data` is an option of `admitgen fit` or `admitgen emit`
/// spelt without its dashes (`live = 100`, `columns = "f,_,re,im"`, `fs = [48000, 96000]`, a flag as
/// `true`), read through the very option definitions of those commands (cli/fit_command.hpp,
/// cli/emit_command.hpp), so a material means exactly `admitgen fit DATA OPTIONS` run in the manifest's
/// folder, then `admitgen emit`. A [defaults] table holds options shared by every material.
#pragma once

#include "library/library.hpp"

#include <string>

namespace admitgen::cli {

/// Reads and checks the whole manifest; throws FileError naming the manifest, the line and the value of
/// the first bad entry (nothing is run or written before the manifest is read).
library::Library read_manifest(const std::string& path);

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
/// @file
/// The prior file of `admitgen fit --priors` (docs/formats.md, "Prior file"): a JSON object
/// {"G_inf": [lo, hi], "A": [...], "lambda": [...], "B": [...], "C": [...], "alpha": [...], "beta": [...]}
/// (any subset) overriding Table 1. Its one reader.
#pragma once

#include "inference/priors.hpp"

#include <string>

namespace admitgen::io {

/// Table 1 overridden by the file at `path`, validated. Throws FileError naming the file and the key.
PriorRanges read_priors_file(const std::string& path);

}  // namespace admitgen::io

// SPDX-License-Identifier: MIT
/// @file
/// The files of one fit, as `admitgen fit --out DIR` writes them: DIR/fit.json, the posterior files beside
/// it and DIR/report.html. One writer, shared by `fit` and the library merge (docs/library.md), so a
/// material of a library and a plain fit of the same data and settings give the same bytes.
#pragma once

#include "data/measurement.hpp"
#include "data/read_options.hpp"
#include "model/fit_record.hpp"
#include "selection/fit.hpp"

#include <string>

namespace admitgen::library {

/// Writes the fit's files into `dir` (which must exist); fit.json appears whole or not at all. Returns the
/// record written as fit.json.
FitRecord write_fit_directory(const std::string& dir, const Measurement& data, const ReadOptions& read,
                              const FitSettings& settings, const FitResult& fit);

}  // namespace admitgen::library

// SPDX-License-Identifier: MIT
/// @file
/// The fit file's record (model/fit_record.hpp) of a fit: per-model parameter summaries, Bayes factors
/// and their errors, the read options, the passive estimates and the selected order's predictive band.
/// io/fit_file.hpp writes it as fit.json.
#pragma once

#include "data/measurement.hpp"
#include "data/read_options.hpp"
#include "model/fit_record.hpp"
#include "selection/fit.hpp"

namespace admitgen {

/// The record of `fit` of `data` (read with `read`) under `settings`, stamped with this version of
/// admitgen. "posterior" is left empty (the caller names the index file once it is written).
FitRecord fit_record(const Measurement& data, const ReadOptions& read, const FitSettings& settings, const FitResult& fit);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// fit.json, schema "admitgen.fit/1" (docs/formats.md), with these extensions: per-model parameter
/// summaries, Bayes-factor errors, the read options, and the selected order's predictive band.
/// Keys keep a fixed order and numbers print so they read back exactly (nlohmann's shortest
/// round-trip form), so equal inputs give equal bytes.
#pragma once

#include "data/measurement.hpp"
#include "data/read_options.hpp"
#include "selection/fit.hpp"

#include <nlohmann/json.hpp>

namespace admitgen {

nlohmann::ordered_json fit_to_json(const Measurement& data, const ReadOptions& read, const FitSettings& settings,
                                   const FitResult& fit);

}  // namespace admitgen

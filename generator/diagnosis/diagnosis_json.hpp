// SPDX-License-Identifier: MIT
/// @file
/// diagnosis.json, schema "admitgen.diagnosis/1" (docs/formats.md), with these extensions: "version",
/// "input" and "settings" (sampler, likelihood, decision rule, the prior of every tried effect);
/// per band "points", "gap_re", "gap_im"; the gap's "total_re", "total_im", "delta_alpha_max",
/// "whiteness"; per stage "cumulative"; per effect "parameter_summary" (mean, std, ci95, max_likelihood,
/// prior), "fixed_parameters", "log_evidence", "log_evidence_error", "band", "whiteness_after";
/// in the verdict "log_bayes_factor_deciban", "margin_deciban", "residual_white_after", "rule".
/// "parameters" holds posterior means. Deterministic: no timing, numbers in shortest round-trip form.
#pragma once

#include "diagnosis/diagnosis.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace admitgen::diagnosis {

nlohmann::ordered_json diagnosis_json(const Diagnosis& diagnosis);

/// diagnosis_json(d).dump(2) + "\n".
std::string diagnosis_text(const Diagnosis& diagnosis);

}  // namespace admitgen::diagnosis

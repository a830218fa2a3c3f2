// SPDX-License-Identifier: MIT
/// @file
/// diagnosis.html of `admitgen diagnose`, built from diagnosis.json (schema admitgen.diagnosis/1) alone,
/// so a saved diagnosis can be rendered again: the verdict in one sentence, the gap per one-third-octave
/// band before and after the best-supported effect, the contribution of each pipeline stage (with
/// --fit), the ranked effect table and the input and settings. Deterministic: equal inputs give equal bytes.
#pragma once

#include "plot/figure.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace admitgen::report {

/// The verdict as one sentence (plain text).
std::string verdict_sentence(const nlohmann::ordered_json& diagnosis);

/// The figures in page order: gap per band; stage contributions when the diagnosis has stages.
std::vector<plot::Figure> diagnosis_figures(const nlohmann::ordered_json& diagnosis);

/// The whole page. Throws InputError if `diagnosis` lacks the gap bands.
std::string diagnosis_report_html(const nlohmann::ordered_json& diagnosis);

/// Writes DIR/diagnosis.html atomically; returns its path.
std::string write_diagnosis_report(const std::string& dir, const nlohmann::ordered_json& diagnosis);

/// Reads DIAGNOSIS.json and writes diagnosis.html beside it; returns its path.
std::string write_diagnosis_report_from_file(const std::string& diagnosis_json_path);

}  // namespace admitgen::report

// SPDX-License-Identifier: MIT
/// @file
/// diagnosis.html of `admitgen diagnose`, built from the diagnosis record alone (what diagnosis.json holds,
/// diagnosis/diagnosis_record.hpp), so a saved diagnosis can be rendered again: the verdict in one sentence, the gap per one-third-octave
/// band before and after the best-supported effect, the contribution of each pipeline stage (with
/// --fit), the ranked effect table and the input and settings. Deterministic: equal inputs give equal bytes.
#pragma once

#include "diagnosis/diagnosis_record.hpp"
#include "plot/figure.hpp"

#include <string>
#include <vector>

namespace admitgen::report {

/// The verdict as one sentence (plain text).
std::string verdict_sentence(const diagnosis::DiagnosisRecord& diagnosis);

/// The figures in page order: gap per band; stage contributions when the diagnosis has stages.
std::vector<plot::Figure> diagnosis_figures(const diagnosis::DiagnosisRecord& diagnosis);

/// The whole page. Throws InputError if `diagnosis` has no gap bands.
std::string diagnosis_report_html(const diagnosis::DiagnosisRecord& diagnosis);

/// Writes DIR/diagnosis.html atomically; returns its path.
std::string write_diagnosis_report(const std::string& dir, const diagnosis::DiagnosisRecord& diagnosis);

}  // namespace admitgen::report

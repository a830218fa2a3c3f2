// SPDX-License-Identifier: MIT
/// @file
/// diagnosis.json (docs/formats.md, "diagnosis.json"): the one reader and the one writer of the diagnosis
/// file, both driven by one field list per record (io/record_fields.hpp). They own its keys, their order and the schema version ("admitgen.diagnosis/3"); everything else
/// takes the typed record, diagnosis/diagnosis_record.hpp. Deterministic: no timing, numbers in shortest
/// round-trip form.
#pragma once

#include "diagnosis/diagnosis_record.hpp"
#include "diagnosis/passive_reference.hpp"
#include "io/key_table.hpp"

#include <string>
#include <vector>

namespace admitgen::io {

/// diagnosis.json's text: the record as JSON indented by 2, then a newline.
std::string diagnosis_text(const diagnosis::DiagnosisRecord& diagnosis);

/// The record of diagnosis.json text. Older files are read too, as the current schema: an
/// "admitgen.diagnosis/2" file (before shares, main cause and dropped members) with those empty; an
/// "admitgen.diagnosis/1" file (before combined explanations) with its verdict's one effect, with the
/// parameters of that effect's entry, as the explanation (none: empty). Throws FileError naming `file` when the text is not JSON, has
/// another schema, lacks a key, holds an unknown key or a value of the wrong type (naming key and value).
diagnosis::DiagnosisRecord parse_diagnosis(const std::string& text, const std::string& file);

/// The keys of diagnosis.json as its field list names them (the table of docs/formats.md, "diagnosis.json").
std::vector<KeyNode> diagnosis_keys();

/// passive_diagnosis.json's text (docs/formats.md, "passive_diagnosis.json"): `diagnose` with physics as the
/// reference (diagnosis/passive_reference.hpp), schema "admitgen.passive_diagnosis/1", indented by 2.
std::string passive_diagnosis_text(const diagnosis::PassiveDiagnosis& diagnosis);

/// Reads and parses the file at `path` (bounded size; FileError if unreadable).
diagnosis::DiagnosisRecord read_diagnosis_file(const std::string& path);

}  // namespace admitgen::io

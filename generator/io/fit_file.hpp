// SPDX-License-Identifier: MIT
/// @file
/// fit.json (docs/formats.md, "fit.json"): the one reader and the one writer of the fit file, both driven
/// by one field list per record (io/record_fields.hpp). They own its keys, their order and the schema
/// version ("admitgen.fit/1"); everything else takes the typed record,
/// model/fit_record.hpp. Keys keep a fixed order and numbers print so they read back exactly (shortest
/// round-trip form), so equal records give equal bytes.
#pragma once

#include "io/key_table.hpp"
#include "model/fit_record.hpp"

#include <string>
#include <vector>

namespace admitgen::io {

/// fit.json's text: the record as JSON indented by 2, then a newline.
std::string fit_text(const FitRecord& fit);

/// The record of fit.json text. Throws FileError naming `file` when the text is not JSON, has another
/// schema, lacks a key, holds an unknown key or a value of the wrong type (naming the key and the value),
/// or selects an order it did not fit.
FitRecord parse_fit(const std::string& text, const std::string& file);

/// Reads and parses the file at `path` (bounded size; FileError if unreadable).
FitRecord read_fit_file(const std::string& path);

/// The keys of fit.json as its field list names them (the table of docs/formats.md, "fit.json").
std::vector<KeyNode> fit_keys();

/// Whether `text` is a JSON document (of any schema).
bool is_json(const std::string& text);

}  // namespace admitgen::io

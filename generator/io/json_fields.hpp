// SPDX-License-Identifier: MIT
/// @file
/// Reading a JSON document into a typed record, with every error in one form: the file, the key's path in
/// the document ("models[2].passive_estimate.sample_rank") and the offending value. An ObjectReader takes
/// the members of one object; finish() refuses members the schema does not know, so a misspelt or foreign
/// key is an error, not silently ignored — except in a document written by a newer admitgen, which may
/// add keys without changing the schema (docs/versioning.md §2) and whose unknown keys are skipped. Used
/// only by the readers of io/.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace admitgen::io {

using Json = nlohmann::ordered_json;

/// Parses `text` as JSON; throws FileError naming `file` if it is not JSON.
Json parse_json(const std::string& text, const std::string& file);

/// Whether `version` ("MAJOR.MINOR.PATCH", a document's "version") is later than this admitgen's; an
/// unreadable version counts as not later.
bool newer_than_this_admitgen(const std::string& version);

/// The JSON object {name: value, ...} of `values`, in their order (the writers' counterpart of
/// Field::numbers_by_name).
Json numbers_by_name_json(const std::vector<std::pair<std::string, double>>& values);

/// `text` (a warning, a note) with each setting it names spelled by its bare key (core/errors.hpp,
/// plain_settings): files name settings, never command-line flags.
Json plain_text(const std::string& text);

/// The JSON array of `texts` (warnings, notes), each setting they name spelled by its bare key
/// (core/errors.hpp, plain_settings): files name settings, never command-line flags.
Json plain_texts(const std::vector<std::string>& texts);

/// One JSON value and where it is, for conversions with errors naming both.
class Field {
 public:
  /// `unknown_keys_allowed`: objects under this value skip keys they do not know (see the file comment).
  Field(const Json& value, const std::string& file, std::string path, bool unknown_keys_allowed = false)
      : v_(&value), file_(&file), path_(std::move(path)), unknown_keys_allowed_(unknown_keys_allowed) {}
  const Json& json() const { return *v_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  bool unknown_keys_allowed() const { return unknown_keys_allowed_; }

  double number() const;
  std::int64_t integer() const;
  std::uint64_t unsigned_integer() const;
  bool boolean() const;
  std::string text() const;
  std::vector<double> numbers() const;
  std::vector<std::string> texts() const;
  std::array<double, 2> number_pair() const;
  /// An object of numbers keyed by name ({"G_inf": 0.1, ...}), in document order.
  std::vector<std::pair<std::string, double>> numbers_by_name() const;
  /// The elements of an array, each with its path ("key[i]").
  std::vector<Field> elements() const;
  /// Throws FileError naming the file, this key and its value: "{what} at key '{path}' (value '...')".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  const Json* v_;
  const std::string* file_;
  std::string path_;
  bool unknown_keys_allowed_;
};

/// The root of a parsed document of schema `schema` (e.g. "admitgen.fit/1"; `kind` names it in the
/// error, e.g. "fit"), allowing unknown keys when a newer admitgen wrote it. Throws FileError naming
/// `file` unless the document is an object whose "schema" is `schema`.
Field document_root(const Json& doc, const std::string& file, const char* schema, const char* kind);

/// The members of one JSON object.
class ObjectReader {
 public:
  /// Throws FileError unless `field` is an object.
  explicit ObjectReader(const Field& field);

  /// The member `key`; throws FileError naming the file and key if it is missing.
  Field required(const char* key);
  /// The member `key`, or nothing when absent.
  std::optional<Field> optional(const char* key);
  /// Throws FileError naming the first member that was not asked for (an unknown key), unless the
  /// document allows unknown keys.
  void finish() const;
  /// Every member in document order (for objects keyed by name); marks them all read.
  std::vector<std::pair<std::string, Field>> members();
  /// The object read.
  const Field& field() const { return field_; }

 private:
  Field field_;
  std::set<std::string> read_;
};

}  // namespace admitgen::io

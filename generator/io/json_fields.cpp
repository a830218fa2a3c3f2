// SPDX-License-Identifier: MIT
#include "io/json_fields.hpp"

#include "core/errors.hpp"
#include "core/version.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <limits>

namespace admitgen::io {

Json parse_json(const std::string& text, const std::string& file) {
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number overflow (1e999)
    throw FileError(file, 0, fmt::format("not JSON ({})", e.what()));
  }
}

bool newer_than_this_admitgen(const std::string& version) {
  const auto parse = [](const std::string& v) -> std::optional<std::array<long, 3>> {
    std::array<long, 3> out{};
    char tail = 0;
    if (std::sscanf(v.c_str(), "%ld.%ld.%ld%c", &out[0], &out[1], &out[2], &tail) != 3) return std::nullopt;
    return out;
  };
  const auto theirs = parse(version), ours = parse(kVersion);
  return theirs && ours && *theirs > *ours;
}

Field document_root(const Json& doc, const std::string& file, const char* schema, const char* kind) {
  const auto found = doc.is_object() ? doc.find("schema") : doc.end();
  if (found == doc.end() || !found->is_string() || *found != schema)
    throw FileError(file, 0, fmt::format("JSON but not an admitgen {} (schema {})", kind, schema));
  const auto version = doc.find("version");
  const bool newer = version != doc.end() && version->is_string() && newer_than_this_admitgen(version->get<std::string>());
  return Field(doc, file, "", newer);
}

void Field::fail(const std::string& what) const {
  std::string value = v_->dump();
  if (value.size() > 80) value = value.substr(0, 77) + "...";
  throw FileError(*file_, 0, fmt::format("{} at key '{}'", what, path_), value);
}

double Field::number() const {
  if (!v_->is_number()) fail("expected a number");
  return v_->get<double>();
}

std::int64_t Field::integer() const {
  if (!v_->is_number_integer() ||
      (v_->is_number_unsigned() && v_->get<std::uint64_t>() > std::uint64_t(std::numeric_limits<std::int64_t>::max())))
    fail("expected an integer");
  return v_->get<std::int64_t>();
}

std::uint64_t Field::unsigned_integer() const {
  if (!v_->is_number_unsigned()) fail("expected a non-negative integer");
  return v_->get<std::uint64_t>();
}

bool Field::boolean() const {
  if (!v_->is_boolean()) fail("expected true or false");
  return v_->get<bool>();
}

std::string Field::text() const {
  if (!v_->is_string()) fail("expected a string");
  return v_->get<std::string>();
}

std::vector<Field> Field::elements() const {
  if (!v_->is_array()) fail("expected an array");
  std::vector<Field> out;
  for (std::size_t i = 0; i < v_->size(); ++i)
    out.emplace_back((*v_)[i], *file_, fmt::format("{}[{}]", path_, i), unknown_keys_allowed_);
  return out;
}

std::vector<double> Field::numbers() const {
  std::vector<double> out;
  for (const auto& e : elements()) out.push_back(e.number());
  return out;
}

std::vector<std::string> Field::texts() const {
  std::vector<std::string> out;
  for (const auto& e : elements()) out.push_back(e.text());
  return out;
}

std::array<double, 2> Field::number_pair() const {
  const auto v = numbers();
  if (v.size() != 2) fail("expected two numbers [lo, hi]");
  return {v[0], v[1]};
}

Json plain_text(const std::string& text) { return plain_settings(text); }

Json plain_texts(const std::vector<std::string>& texts) {
  Json out = Json::array();
  for (const auto& t : texts) out.push_back(plain_settings(t));
  return out;
}

Json numbers_by_name_json(const std::vector<std::pair<std::string, double>>& values) {
  Json out = Json::object();
  for (const auto& [name, v] : values) out[name] = v;
  return out;
}

std::vector<std::pair<std::string, double>> Field::numbers_by_name() const {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [name, v] : ObjectReader(*this).members()) out.emplace_back(name, v.number());
  return out;
}

ObjectReader::ObjectReader(const Field& field) : field_(field) {
  if (!field.json().is_object()) field.fail("expected an object");
}

namespace {
std::string member_path(const std::string& object, const std::string& key) {
  return object.empty() ? key : object + "." + key;
}
}  // namespace

std::optional<Field> ObjectReader::optional(const char* key) {
  read_.insert(key);
  const auto it = field_.json().find(key);
  if (it == field_.json().end()) return std::nullopt;
  return Field(*it, field_.file(), member_path(field_.path(), key), field_.unknown_keys_allowed());
}

Field ObjectReader::required(const char* key) {
  if (auto f = optional(key)) return *f;
  throw FileError(field_.file(), 0, fmt::format("missing key '{}'", member_path(field_.path(), key)));
}

std::vector<std::pair<std::string, Field>> ObjectReader::members() {
  std::vector<std::pair<std::string, Field>> out;
  for (auto it = field_.json().begin(); it != field_.json().end(); ++it) {
    read_.insert(it.key());
    out.emplace_back(it.key(), Field(it.value(), field_.file(), member_path(field_.path(), it.key()),
                                     field_.unknown_keys_allowed()));
  }
  return out;
}

void ObjectReader::finish() const {
  if (field_.unknown_keys_allowed()) return;
  for (auto it = field_.json().begin(); it != field_.json().end(); ++it)
    if (read_.count(it.key()) == 0)
      throw FileError(field_.file(), 0, fmt::format("unknown key '{}'", member_path(field_.path(), it.key())));
}

}  // namespace admitgen::io

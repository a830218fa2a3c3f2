// SPDX-License-Identifier: MIT
/// @file
/// One field list per record drives its writer, its reader and its key table (docs/formats.md, "Records,
/// readers and writers"). A record's field list is an overload `void fields(V& v, R& r)` for any visitor V
/// that names each member once, with its key, in file order:
///
///   v("key", r.member)                a value; a std::optional member is left out of the file when empty
///   v("key", r.member, kNullable)     a std::optional member written as null when empty (the key is required;
///                                     with kOptional a file may also lack it)
///   v("key", r.member, kPlain)        a text or texts that may name settings: written by their bare keys
///                                     (core/errors.hpp, plain_settings)
///   v.pair("key", r.lo, r.hi)         two numbers as one [lo, hi]
///   v.object("key", [&](auto& w) {…}) an object whose members are members of the same record
///   v.by_name("key", r.records)       records with a member `name`, as an object {name: {their other members}}
///   v.named(r.values)                 values keyed by name (std::vector<std::pair<std::string, T>>), each
///                                     its own key of this object (listed as the key "*")
///   v.custom("key", r.member, codec)  a member with its own conversion (codec.write, codec.read)
///   v.ignored("key")                  a key earlier versions wrote: read and dropped, never written
///   v.since(n, [&](auto& w) {…})      keys added by schema version n: a file of an earlier version lacks
///                                     them and its reader leaves their members as they are
///   v.expect(condition, "what")       a condition on the members read so far, which the reader enforces
///   fields(v, r.part)                 the members of a record part inlined into this object
///
/// A value is a text, a number, an integer, a boolean, a vector or [lo, hi] pair of them, an object keyed by
/// name (std::vector<std::pair<std::string, T>>), a record with a field list, or a vector of records. The
/// visitors: write_record (the record as JSON), read_record (JSON into the record, every error naming the
/// file, the key's path and the value: io/json_fields.hpp) and record_keys (the key table, which the tests
/// compare with docs/formats.md). Used only inside io/.
#pragma once

#include "io/json_fields.hpp"
#include "io/key_table.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace admitgen::io {

/// Flags of a member in a field list.
enum FieldFlags : unsigned {
  kNullable = 1,  ///< std::optional: null when empty, the key required (default: the key is left out)
  kPlain = 2,     ///< texts that may name settings: written by their bare keys
  kOptional = 4,  ///< with kNullable: a file may also lack the key (earlier versions did not write it)
};

/// The schema version a reader reads when the file is of the current one (see since()).
inline constexpr int kLatestVersion = 1 << 30;

/// A visitor that only finds out whether a type has a field list (in this namespace, so that the field
/// lists are found by argument-dependent lookup).
struct FieldProbe {
  template <class M>
  void operator()(const char*, M&, unsigned = 0) {}
  template <class A, class B>
  void pair(const char*, A&, B&) {}
  template <class F>
  void object(const char*, F&&) {}
  template <class M, class C>
  void custom(const char*, M&, const C&) {}
  template <class R>
  void by_name(const char*, std::vector<R>&) {}
  template <class T>
  void named(std::vector<std::pair<std::string, T>>&) {}
  void ignored(const char*) {}
  template <class F>
  void since(int, F&&) {}
  void expect(bool, const std::string&) {}
};

namespace detail {

template <class T>
struct is_optional : std::false_type {};
template <class T>
struct is_optional<std::optional<T>> : std::true_type {};
template <class T>
struct is_keyed : std::false_type {};
template <class T>
struct is_keyed<std::vector<std::pair<std::string, T>>> : std::true_type {};

template <class T, class = void>
struct has_fields : std::false_type {};
template <class T>
struct has_fields<T, std::void_t<decltype(fields(std::declval<FieldProbe&>(), std::declval<T&>()))>> : std::true_type {};
/// A vector of records (an array of objects).
template <class T>
struct is_records : std::false_type {};
template <class T>
struct is_records<std::vector<T>> : has_fields<T> {};

}  // namespace detail

template <class T>
Json write_record(const T& record);
template <class T>
void read_record(const Field& field, T& record, int version = kLatestVersion);
template <class T>
std::vector<KeyNode> record_keys();

/// The JSON of one value of a field list (see the file comment).
template <class T>
Json value_json(const T& v, unsigned flags) {
  if constexpr (detail::has_fields<T>::value) {
    return write_record(v);
  } else if constexpr (detail::is_keyed<T>::value) {
    Json out = Json::object();
    for (const auto& [name, value] : v) out[name] = value_json(value, flags);
    return out;
  } else if constexpr (detail::is_records<T>::value) {
    Json out = Json::array();
    for (const auto& e : v) out.push_back(write_record(e));
    return out;
  } else if constexpr (std::is_same_v<T, std::string>) {
    return (flags & kPlain) ? plain_text(v) : Json(v);
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    return (flags & kPlain) ? plain_texts(v) : Json(v);
  } else {
    return Json(v);
  }
}

/// Reads one value of a field list from `f` into `v` (see the file comment), from a file of schema
/// version `version`.
template <class T>
void read_value(const Field& f, T& v, unsigned flags, int version) {
  if constexpr (detail::has_fields<T>::value) {
    read_record(f, v, version);
  } else if constexpr (detail::is_keyed<T>::value) {
    v.clear();
    for (const auto& [name, field] : ObjectReader(f).members()) {
      typename T::value_type::second_type value{};
      read_value(field, value, flags, version);
      v.emplace_back(name, std::move(value));
    }
  } else if constexpr (detail::is_records<T>::value) {
    v.clear();
    for (const auto& e : f.elements()) read_record(e, v.emplace_back(), version);
  } else if constexpr (std::is_same_v<T, std::string>) {
    v = f.text();
  } else if constexpr (std::is_same_v<T, double>) {
    v = f.number();
  } else if constexpr (std::is_same_v<T, bool>) {
    v = f.boolean();
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    v = f.unsigned_integer();
  } else if constexpr (std::is_same_v<T, std::int64_t>) {
    v = f.integer();
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    v = f.numbers();
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    v = f.texts();
  } else {
    static_assert(std::is_same_v<T, std::array<double, 2>>, "a member type the field lists do not know");
    v = f.number_pair();
  }
}

/// The key-table shape of one value of a field list.
template <class T>
KeyNode value_keys(const char* key) {
  KeyNode n{key, false, KeyNode::Shape::value, {}};
  if constexpr (detail::has_fields<T>::value) {
    n.shape = KeyNode::Shape::object;
    n.children = record_keys<T>();
  } else if constexpr (detail::is_keyed<T>::value) {
    n.shape = KeyNode::Shape::keyed;
  } else if constexpr (detail::is_records<T>::value) {
    n.shape = KeyNode::Shape::records;
    n.children = record_keys<typename T::value_type>();
  }
  return n;
}

/// What every visitor but the reader does alike: it visits the keys of every schema version, skips the keys
/// only read, and leaves the reader's conditions to it.
template <class Visitor>
class EveryVersion {
 public:
  void ignored(const char*) {}
  template <class F>
  void since(int, F&& members) {
    members(static_cast<Visitor&>(*this));
  }
  void expect(bool, const std::string&) {}
};

/// Writes the members a field list names into one JSON object.
class JsonWriter : public EveryVersion<JsonWriter> {
 public:
  explicit JsonWriter(Json& out) : out_(&out) {}
  template <class M>
  void operator()(const char* key, const M& m, unsigned flags = 0) {
    if constexpr (detail::is_optional<M>::value) {
      if (m)
        (*out_)[key] = value_json(*m, flags);
      else if (flags & kNullable)
        (*out_)[key] = nullptr;
    } else {
      (*out_)[key] = value_json(m, flags);
    }
  }
  void pair(const char* key, double lo, double hi) { (*out_)[key] = {lo, hi}; }
  template <class F>
  void object(const char* key, F&& members) {
    Json sub = Json::object();
    JsonWriter w(sub);
    members(w);
    (*out_)[key] = std::move(sub);
  }
  template <class M, class C>
  void custom(const char* key, const M& m, const C& codec) {
    (*out_)[key] = codec.write(m);
  }
  template <class R>
  void by_name(const char* key, const std::vector<R>& records) {
    Json out = Json::object();
    for (const auto& r : records) out[r.name] = write_record(r);
    (*out_)[key] = std::move(out);
  }
  template <class T>
  void named(const std::vector<std::pair<std::string, T>>& values) {
    for (const auto& [name, value] : values) (*out_)[name] = value_json(value, 0);
  }

 private:
  Json* out_;
};

/// Reads the members a field list names from one JSON object (ObjectReader: a missing required key, a
/// value of the wrong type and an unknown key are errors naming the file and the key's path).
class JsonReader {
 public:
  JsonReader(ObjectReader& in, int version) : in_(&in), version_(version) {}
  template <class M>
  void operator()(const char* key, M& m, unsigned flags = 0) {
    if constexpr (detail::is_optional<M>::value) {
      m.reset();
      const auto f = (flags & kNullable) && !(flags & kOptional) ? std::optional<Field>(in_->required(key))
                                                                  : in_->optional(key);
      if (!f || ((flags & kNullable) && f->json().is_null())) return;
      typename M::value_type value{};
      read_value(*f, value, flags, version_);
      m = std::move(value);
    } else {
      read_value(in_->required(key), m, flags, version_);
    }
  }
  void pair(const char* key, double& lo, double& hi) {
    const auto v = in_->required(key).number_pair();
    lo = v[0];
    hi = v[1];
  }
  template <class F>
  void object(const char* key, F&& members) {
    ObjectReader sub(in_->required(key));
    JsonReader r(sub, version_);
    members(r);
    sub.finish();
  }
  template <class M, class C>
  void custom(const char* key, M& m, const C& codec) {
    codec.read(in_->required(key), m);
  }
  template <class R>
  void by_name(const char* key, std::vector<R>& records) {
    records.clear();
    for (const auto& [name, field] : ObjectReader(in_->required(key)).members()) {
      R& r = records.emplace_back();
      r.name = name;
      read_record(field, r, version_);
    }
  }
  void ignored(const char* key) { in_->optional(key); }
  template <class F>
  void since(int version, F&& members) {
    if (version_ >= version) members(*this);
  }
  void expect(bool condition, const std::string& what) {
    if (!condition) in_->field().fail(what);
  }

 private:
  ObjectReader* in_;
  int version_;
};

/// Lists the keys a field list names (the key table).
class KeyLister : public EveryVersion<KeyLister> {
 public:
  explicit KeyLister(std::vector<KeyNode>& out) : out_(&out) {}
  template <class M>
  void operator()(const char* key, const M&, unsigned flags = 0) {
    if constexpr (detail::is_optional<M>::value) {
      out_->push_back(value_keys<typename M::value_type>(key));
      out_->back().optional = !(flags & kNullable) || (flags & kOptional);
      out_->back().nullable = (flags & kNullable) != 0;
    } else {
      out_->push_back(value_keys<M>(key));
    }
  }
  void pair(const char* key, double, double) { out_->push_back({key, false, KeyNode::Shape::value, {}}); }
  template <class F>
  void object(const char* key, F&& members) {
    KeyNode n{key, false, KeyNode::Shape::object, {}};
    KeyLister sub(n.children);
    members(sub);
    out_->push_back(std::move(n));
  }
  template <class M, class C>
  void custom(const char* key, const M&, const C&) {
    out_->push_back({key, false, KeyNode::Shape::value, {}});
  }
  template <class R>
  void by_name(const char* key, const std::vector<R>&) {
    out_->push_back({key, false, KeyNode::Shape::keyed_records, record_keys<R>()});
  }
  template <class T>
  void named(const std::vector<std::pair<std::string, T>>&) {
    out_->push_back(value_keys<T>("*"));
  }

 private:
  std::vector<KeyNode>* out_;
};

/// The record as one JSON object, in its field list's order. (The field list takes a mutable record so
/// that one list serves the reader too; the writer only reads it.)
template <class T>
Json write_record(const T& record) {
  Json out = Json::object();
  JsonWriter w(out);
  fields(w, const_cast<T&>(record));
  return out;
}

/// Reads the record from the JSON object `field` of a file of schema version `version`; unknown keys are
/// refused (ObjectReader::finish).
template <class T>
void read_record(const Field& field, T& record, int version) {
  ObjectReader in(field);
  JsonReader r(in, version);
  fields(r, record);
  in.finish();
}

/// The keys of a record, in its field list's order.
template <class T>
std::vector<KeyNode> record_keys() {
  std::vector<KeyNode> out;
  KeyLister l(out);
  T record{};
  fields(l, record);
  return out;
}

}  // namespace admitgen::io

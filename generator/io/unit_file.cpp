// SPDX-License-Identifier: MIT
#include "io/unit_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "io/record_fields.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace admitgen::io {
namespace {

constexpr const char* kSchema = "admitgen.unit/2";

/// One line of free text (newlines would break the line structure; none of the texts written holds one).
std::string one_line(std::string s) {
  for (auto& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

void put(std::string& out, const char* key, double v) { out += fmt::format("{} {:a}\n", key, v); }
void put(std::string& out, const char* key, long v) { out += fmt::format("{} {}\n", key, v); }
void put(std::string& out, const char* key, const std::string& v) { out += fmt::format("{} {}\n", key, one_line(v)); }
void put(std::string& out, const char* key, const std::vector<double>& v) {
  out += fmt::format("{} {}\n", key, v.size());
  for (double x : v) out += fmt::format("{:a}\n", x);
}

/// Reads the lines of a unit file in order, each "key value", with errors naming file and line.
class Lines {
 public:
  Lines(std::string path, const std::string& text) : path_(std::move(path)), in_(text) {}
  std::string text(const char* key) {
    const std::string line = next();
    const auto space = line.find(' ');
    const std::string k = line.substr(0, space);
    if (k != key) fail(fmt::format("expected '{}'", key), line);
    return space == std::string::npos ? std::string() : line.substr(space + 1);
  }
  double number(const char* key) { return parse_double(text(key)); }
  long integer(const char* key) {
    const std::string t = text(key);
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0' || errno != 0) fail(fmt::format("'{}' is not an integer", key), t);
    return v;
  }
  std::vector<double> numbers(const char* key) {
    const long n = integer(key);
    if (n < 0) fail(fmt::format("negative count of '{}'", key), std::to_string(n));
    std::vector<double> v(static_cast<std::size_t>(n));
    for (auto& x : v) x = parse_double(next());
    return v;
  }
  [[noreturn]] void fail(const std::string& what, const std::string& value) const {
    throw FileError(path_, line_, what, value);
  }
  /// Fails naming the value of the line read last.
  [[noreturn]] void fail(const std::string& what) const { fail(what, value_); }

 private:
  std::string next() {
    std::string line;
    if (!std::getline(in_, line)) fail("unexpected end of a unit file", "");
    ++line_;
    const auto space = line.find(' ');
    value_ = space == std::string::npos ? line : line.substr(space + 1);
    return line;
  }
  double parse_double(const std::string& t) {
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0') fail("not a number", t);
    return v;
  }
  std::string path_;
  std::istringstream in_;
  long line_ = 0;
  std::string value_;
};

/// Writes the members a field list names as lines "key value" (io/record_fields.hpp).
class LineWriter : public EveryVersion<LineWriter> {
 public:
  explicit LineWriter(std::string& out) : out_(&out) {}
  template <class M>
  void operator()(const char* key, const M& m, unsigned = 0) {
    if constexpr (std::is_same_v<M, int>)
      put(*out_, key, static_cast<long>(m));
    else
      put(*out_, key, m);
  }
  template <class M, class C>
  void custom(const char* key, const M& m, const C& codec) {
    put(*out_, key, codec.write(m));
  }

 private:
  std::string* out_;
};

/// Reads the members a field list names from the lines, in order.
class LineReader {
 public:
  explicit LineReader(Lines& in) : in_(&in) {}
  void operator()(const char* key, std::string& m, unsigned = 0) { m = in_->text(key); }
  void operator()(const char* key, double& m, unsigned = 0) { m = in_->number(key); }
  void operator()(const char* key, long& m, unsigned = 0) { m = in_->integer(key); }
  void operator()(const char* key, int& m, unsigned = 0) { m = static_cast<int>(in_->integer(key)); }
  void operator()(const char* key, std::vector<double>& m, unsigned = 0) { m = in_->numbers(key); }
  template <class M, class C>
  void custom(const char* key, M& m, const C& codec) {
    codec.read(*in_, in_->text(key), m);
  }
  void expect(bool condition, const std::string& what) {
    if (!condition) in_->fail(what);
  }

 private:
  Lines* in_;
};

/// An order by its name ("Q1S1").
struct OrderLine {
  std::string write(const Order& order) const { return order.name(); }
  void read(const Lines& in, const std::string& text, Order& order) const {
    try {
      order = Order::parse(text);
    } catch (const InputError&) {
      in.fail("not an order", text);
    }
  }
};

}  // namespace

/// The field list of a unit file (docs/formats.md, "Library unit results").
template <class V>
void fields(V& v, UnitResult& u) {
  ModelResult& m = u.model;
  NestedRun& r = m.run;
  v("key", u.key);
  v.custom("order", m.order, OrderLine{});
  v("live", m.live);
  v("seconds", m.seconds);
  v("sampler", m.sampler);
  v("sampler_note", m.sampler_note);
  v("dim", r.dim);
  v.expect(r.dim == m.order.dim(), fmt::format("dim is not that of {}", m.order.name()));
  v("log_z", r.log_z);
  v("log_z_error", r.log_z_error);
  v("information", r.information);
  v("max_log_likelihood", r.max_log_likelihood);
  v("calls", r.calls);
  v("iterations", r.iterations);
  v("stopped_by", r.stopped_by);
  v("log_support_fraction", r.log_support_fraction);
  v("samples", r.samples);
  v("log_likelihood", r.log_likelihood);
  v("log_weight", r.log_weight);
}

std::string unit_text(const UnitResult& u) {
  std::string out = std::string(kSchema) + "\n";
  LineWriter w(out);
  fields(w, const_cast<UnitResult&>(u));  // one field list for the writer and the reader: the writer only reads
  out += "end\n";
  return out;
}

UnitResult read_unit_file(const std::string& path) {
  Lines in(path, read_bounded(path, std::size_t{1} << 30, "unit file"));
  if (const std::string schema = in.text(kSchema); !schema.empty()) in.fail("unknown schema", schema);
  UnitResult u;
  LineReader reader(in);
  fields(reader, u);
  ModelResult& m = u.model;
  const NestedRun& r = m.run;
  if (r.samples.size() != r.log_likelihood.size() * static_cast<std::size_t>(r.dim) ||
      r.log_weight.size() != r.log_likelihood.size())
    in.fail("samples, log_likelihood and log_weight disagree in length", std::to_string(r.log_likelihood.size()));
  if (const std::string end = in.text("end"); !end.empty()) in.fail("expected 'end'", end);
  m.parameters = summarize(r, m.order.parameter_names());
  return u;
}

std::vector<KeyNode> unit_keys() { return record_keys<UnitResult>(); }

std::string unit_file_key(const std::string& path) {
  std::ifstream f(path);
  std::string schema, key;
  if (!std::getline(f, schema) || schema != kSchema || !std::getline(f, key) || key.rfind("key ", 0) != 0) return {};
  // A whole file ends with "end": look at its last line.
  f.seekg(0, std::ios::end);
  const auto size = static_cast<long>(f.tellg());
  if (size < 4) return {};
  f.seekg(size - 4);
  std::string tail(4, '\0');
  f.read(tail.data(), 4);
  return tail == "end\n" ? key.substr(4) : std::string();
}

}  // namespace admitgen::io

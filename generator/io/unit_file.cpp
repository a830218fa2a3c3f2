// SPDX-License-Identifier: MIT
#include "io/unit_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"

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

 private:
  std::string next() {
    std::string line;
    if (!std::getline(in_, line)) fail("unexpected end of a unit file", "");
    ++line_;
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
};

}  // namespace

std::string unit_text(const UnitResult& u) {
  const ModelResult& m = u.model;
  const NestedRun& r = m.run;
  std::string out = std::string(kSchema) + "\n";
  put(out, "key", u.key);
  put(out, "order", m.order.name());
  put(out, "live", static_cast<long>(m.live));
  put(out, "seconds", m.seconds);
  put(out, "sampler", m.sampler);
  put(out, "sampler_note", m.sampler_note);
  put(out, "dim", static_cast<long>(r.dim));
  put(out, "log_z", r.log_z);
  put(out, "log_z_error", r.log_z_error);
  put(out, "information", r.information);
  put(out, "max_log_likelihood", r.max_log_likelihood);
  put(out, "calls", r.calls);
  put(out, "iterations", r.iterations);
  put(out, "stopped_by", r.stopped_by);
  put(out, "log_support_fraction", r.log_support_fraction);
  put(out, "samples", r.samples);
  put(out, "log_likelihood", r.log_likelihood);
  put(out, "log_weight", r.log_weight);
  out += "end\n";
  return out;
}

UnitResult read_unit_file(const std::string& path) {
  Lines in(path, read_bounded(path, std::size_t{1} << 30, "unit file"));
  if (const std::string schema = in.text(kSchema); !schema.empty()) in.fail("unknown schema", schema);
  UnitResult u;
  u.key = in.text("key");
  ModelResult& m = u.model;
  const std::string order = in.text("order");
  try {
    m.order = Order::parse(order);
  } catch (const InputError&) {
    in.fail("not an order", order);
  }
  m.live = static_cast<int>(in.integer("live"));
  m.seconds = in.number("seconds");
  m.sampler = in.text("sampler");
  m.sampler_note = in.text("sampler_note");
  NestedRun& r = m.run;
  r.dim = static_cast<int>(in.integer("dim"));
  if (r.dim != m.order.dim()) in.fail(fmt::format("dim is not that of {}", m.order.name()), std::to_string(r.dim));
  r.log_z = in.number("log_z");
  r.log_z_error = in.number("log_z_error");
  r.information = in.number("information");
  r.max_log_likelihood = in.number("max_log_likelihood");
  r.calls = in.integer("calls");
  r.iterations = in.integer("iterations");
  r.stopped_by = in.text("stopped_by");
  r.log_support_fraction = in.number("log_support_fraction");
  r.samples = in.numbers("samples");
  r.log_likelihood = in.numbers("log_likelihood");
  r.log_weight = in.numbers("log_weight");
  if (r.samples.size() != r.log_likelihood.size() * static_cast<std::size_t>(r.dim) ||
      r.log_weight.size() != r.log_likelihood.size())
    in.fail("samples, log_likelihood and log_weight disagree in length", std::to_string(r.log_likelihood.size()));
  if (const std::string end = in.text("end"); !end.empty()) in.fail("expected 'end'", end);
  m.parameters = summarize(r, m.order.parameter_names());
  return u;
}

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

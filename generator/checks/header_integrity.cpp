// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"

#include "codegen/runtime_filter.hpp"
#include "core/text.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <map>
#include <tuple>
#include <optional>

namespace admitgen::checks {
namespace {

constexpr std::string_view kBlanks = " \t\r\n";  // between the tokens of a C initialiser

/// The comma-separated initialiser tokens of `static const TYPE NAME[...] = { ... };` or
/// `static const TYPE NAME = { ... };` (comments removed), or nothing if the declaration is absent.
std::optional<std::vector<std::string>> initialiser(const std::string& text, const std::string& type,
                                                    const std::string& name, bool array) {
  const std::string decl = "static const " + type + " " + name + (array ? "[" : " = {");
  const std::size_t at = text.find(decl);
  if (at == std::string::npos) return std::nullopt;
  const std::size_t open = text.find('{', at), close = text.find("};", at);
  if (open == std::string::npos || close == std::string::npos || close < open) return std::nullopt;
  std::string body;
  for (std::size_t i = open + 1; i < close; ++i) {
    if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string::npos || end > close) return std::nullopt;
      i = end + 1;
      continue;
    }
    body += text[i];
  }
  std::vector<std::string> tokens;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= body.size(); ++i)
    if (i == body.size() || body[i] == ',') {
      const auto t = trim(std::string_view(body).substr(start, i - start), kBlanks);
      if (!t.empty()) tokens.emplace_back(t);
      start = i + 1;
    }
  return tokens;
}

/// Exact numeric value of a C literal token ("-12", "1u", "0.25f", "1e-3"), or nothing.
std::optional<double> literal(const std::string& t, bool is_float) {
  char* end = nullptr;
  const double v = is_float ? double(std::strtof(t.c_str(), &end)) : double(std::strtoll(t.c_str(), &end, 10));
  if (end == t.c_str()) return std::nullopt;
  const std::string rest(end);
  if (!(rest.empty() || rest == "f" || rest == "u")) return std::nullopt;
  return v;
}

void compare(CheckResult& r, const std::string& text, const std::string& type, const std::string& name, bool array,
             const std::vector<double>& expected, bool is_float, std::size_t first, std::size_t count) {
  const auto tokens = initialiser(text, type, name, array);
  if (!tokens) {
    r.fail(fmt::format("{}: declaration missing or unreadable", name));
    return;
  }
  if (tokens->size() < first + count) {
    r.fail(fmt::format("{}: {} initialisers, the machine-readable block needs {}", name, tokens->size(), first + count));
    return;
  }
  for (std::size_t i = 0; i < count; ++i) {
    const auto v = literal((*tokens)[first + i], is_float);
    if (!v || *v != expected[i])
      r.fail(fmt::format("{}[{}] is '{}' in the C table but {} in the machine-readable block: the table was edited",
                         name, first + i, (*tokens)[first + i], expected[i]));
  }
}

/// Compares the model struct's fields, initialised by name (`ADMITGEN_RT_FIELD(name) value`,
/// templates/admitgen_boundary.h.in), with the expected {field, value, is_float}.
void compare_fields(CheckResult& r, const std::string& text, const std::string& type, const std::string& name,
                    const std::vector<std::tuple<std::string, double, bool>>& expected) {
  const auto tokens = initialiser(text, type, name, false);
  if (!tokens) {
    r.fail(fmt::format("{}: declaration missing or unreadable", name));
    return;
  }
  const std::string tag = "ADMITGEN_RT_FIELD(";
  std::map<std::string, std::string> fields;
  for (const auto& t : *tokens) {
    const std::size_t close = t.find(')');
    if (t.compare(0, tag.size(), tag) != 0 || close == std::string::npos) continue;
    fields[t.substr(tag.size(), close - tag.size())] = trim(std::string_view(t).substr(close + 1), kBlanks);
  }
  for (const auto& [field, value, is_float] : expected) {
    const auto it = fields.find(field);
    if (it == fields.end()) {
      r.fail(fmt::format("{}.{}: not initialised by name in the C struct", name, field));
      continue;
    }
    const auto v = literal(it->second, is_float);
    if (!v || *v != value)
      r.fail(fmt::format("{}.{} is '{}' in the C struct but {} in the machine-readable block: the struct was edited",
                         name, field, it->second, value));
  }
}

/// A rate's tables as the runtime reads them (codegen/runtime_filter.hpp), entries as doubles.
struct Tables {
  std::vector<double> fir, real, pair;
};
template <typename Sample>
Tables tables(const codegen::RuntimeModel<Sample>& t) {
  return {{t.fir().begin(), t.fir().end()}, {t.real().begin(), t.real().end()}, {t.pair().begin(), t.pair().end()}};
}

}  // namespace

CheckResult check_header_integrity(const CheckSubject& s) {
  CheckResult r;
  r.name = "header_integrity";
  if (!s.header) return r.not_applicable("not a header");
  r.method = "every C table and model struct equals the machine-readable block the other checks read";
  const auto& h = *s.header;
  const bool f32 = h.format == codegen::Format::f32;
  const std::string fmt_name = codegen::format_name(h.format);
  const bool wide = !h.rates.empty() && h.rates.front().fixed && h.rates.front().fixed->wide();
  const std::string ctype = codegen::table_ctype(h.format, wide);
  std::size_t values = 0;
  for (const auto& rate : h.rates) {
    const std::string base = fmt::format("{}_{}", h.name, rate.fs_hz);
    const auto& m = rate.model;
    const Tables t = f32 ? tables(codegen::RuntimeModelF32(codegen::to_float(m), rate.fs_hz))
                     : h.format == codegen::Format::q31 || rate.fixed->wide()
                         ? tables(codegen::RuntimeModelQ31(*rate.fixed, rate.fs_hz))
                                                        : tables(codegen::RuntimeModelQ15(*rate.fixed, rate.fs_hz));
    const auto& [fir, real, pair] = t;
    compare(r, s.header_text, ctype, base + "_fir", true, fir, f32, 0, fir.size());
    compare(r, s.header_text, ctype, base + "_real", true, real, f32, 0, real.size());
    compare(r, s.header_text, ctype, base + "_pair", true, pair, f32, 0, pair.size());
    std::vector<std::tuple<std::string, double, bool>> fields{
        {"abi_version", double(codegen::kRuntimeAbi), false}, {"fs_hz", double(rate.fs_hz), false},
        {"n_fir", double(m.fir.size()), false},               {"n_real", double(m.real.size()), false},
        {"n_pair", double(m.pair.size()), false}};
    if (f32) {
      fields.emplace_back("h0", double(codegen::to_float(m).h0), true);
    } else {
      fields.emplace_back("out_shift", double(rate.fixed->out_shift), false);
      fields.emplace_back("acc_shift", double(rate.fixed->acc_shift), false);
    }
    compare_fields(r, s.header_text, "admitgen_rt_model_" + fmt_name, base, fields);
    values += fir.size() + real.size() + pair.size() + fields.size();
  }
  r.details = HeaderIntegrityDetails{values};
  r.summary = r.failures.empty() ? fmt::format("{} table values and struct fields match the block", values)
                                 : "the C tables differ from the machine-readable block";
  return r;
}

}  // namespace admitgen::checks

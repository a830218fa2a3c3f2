// SPDX-License-Identifier: MIT
#include "io/model_block.hpp"

#include "core/errors.hpp"
#include "core/version.hpp"
#include "io/json_fields.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace admitgen::io {
namespace {

using codegen::DiscreteModel;
using codegen::EmittedHeader;
using codegen::EmittedRate;
using codegen::FixedCoefficients;
using codegen::Format;
using codegen::PairTerm;
using codegen::PassivityEnforcement;
using codegen::RealTerm;

// ---- writer ---------------------------------------------------------------------------------------

Json coefficient_json(const EmittedRate& r, Format format) {
  Json j;
  if (format == Format::f32) {
    Json real = Json::array(), pair = Json::array();
    for (const auto& t : r.f32.real) real.push_back({double(t[0]), double(t[1])});
    for (const auto& p : r.f32.pair) pair.push_back({double(p[0]), double(p[1]), double(p[2]), double(p[3]), double(p[4])});
    j = {{"h0", double(r.f32.h0)}, {"fir", std::vector<double>(r.f32.fir.begin(), r.f32.fir.end())}, {"real", real}, {"pair", pair}};
  } else {
    const auto& q = *r.fixed;
    Json real = Json::array(), pair = Json::array();
    for (const auto& t : q.real) real.push_back({t.eps, t.shift, t.c});
    for (const auto& p : q.pair) pair.push_back({p.e_r, p.p_i, p.g, p.shift, p.c_r, p.c_i});
    j = {{"bits", q.bits}, {"out_shift", q.out_shift}, {"y_exp", q.y_exp}, {"acc_shift", q.acc_shift},
         {"l1_norm", q.l1_norm}, {"zero_decay_bound", q.zero_decay_bound()}, {"fir", q.fir}, {"real", real}, {"pair", pair}};
  }
  return j;
}

Json double_json(const DiscreteModel& m) {
  Json real = Json::array(), pair = Json::array();
  for (const auto& t : m.real) real.push_back({t.eps, t.c});
  for (const auto& p : m.pair) pair.push_back({p.e_r, p.p_i, p.g, 2.0 * p.c.real(), -2.0 * p.c.imag()});
  return {{"fir", m.fir}, {"real", real}, {"pair", pair}};
}

Json enforcement_json(const std::optional<PassivityEnforcement>& p) {
  if (!p) return nullptr;
  return Json{{"applied_to", p->applied_to},
              {"negative_bands_before", p->negative_bands_before},
              {"certified", p->certified},
              {"constraint_rounds", p->constraint_rounds},
              {"max_rel_change_in_data_band", p->max_rel_change_in_data_band},
              {"max_rel_change_outside_data_band", p->max_rel_change_outside_data_band}};
}

/// The notes as files read them: each setting named by its bare key (core/errors.hpp, plain_settings).
std::vector<std::string> plain_notes(const std::vector<std::string>& notes) {
  std::vector<std::string> plain;
  for (const auto& n : notes) plain.push_back(plain_settings(n));
  return plain;
}

Json emission_json(const codegen::Emission& e) {
  Json rates = Json::array();
  for (const auto& r : e.rates) {
    Json j{{"fs_hz", r.fs_hz},
           {"method", e.settings.refit_to_stored_poles ? "matched_exponential_refit_to_stored_poles"
                                                       : "matched_exponential_refit"},
           {"refit_max_rel_error", r.model.refit_max_rel_error},
           {"plrc_max_rel_error", r.model.plrc_max_rel_error},
           {"passive_certified", r.model.passive_certified},
           {"passive_constraint_rounds", r.model.passive_rounds},
           {"folded", r.model.folded},
           {"fidelity", {{"max_rel_deviation_in_band", r.fidelity.max_rel_deviation},
                         {"at_hz", r.fidelity.at_hz},
                         {"max_rel_deviation_above_band", r.fidelity.max_rel_deviation_above},
                         {"noise_floor", r.fidelity.noise_floor},
                         {"min_full_scale_snr_db", r.fidelity.min_snr_db}}},
           {"double", double_json(r.model)}};
    j[format_name(e.settings.format)] = coefficient_json(r, e.settings.format);
    rates.push_back(j);
  }
  const auto names = e.surface.order.parameter_names();
  return Json{{"schema", kModelBlockSchema},
              {"version", kVersion},
              {"abi", codegen::kRuntimeAbi},
              {"name", e.settings.name},
              {"format", format_name(e.settings.format)},
              {"fit", {{"file", e.fit_name}, {"version", e.fit_version}, {"input_sha256", e.input_sha256}, {"seed", e.seed}}},
              {"order", e.surface.order.name()},
              {"estimate", estimate_name(e.estimate)},
              {"continuous", {{"names", names},
                              {"theta", std::vector<double>(e.surface.theta.data(),
                                                            e.surface.theta.data() + e.surface.theta.size())}}},
              {"data_f_min_hz", *std::min_element(e.data_f_hz.begin(), e.data_f_hz.end())},
              {"data_f_max_hz", *std::max_element(e.data_f_hz.begin(), e.data_f_hz.end())},
              {"notes", plain_notes(e.notes)},
              {"passivity_enforcement", enforcement_json(e.enforcement)},
              {"rates", rates}};
}

// ---- reader ---------------------------------------------------------------------------------------

/// Rebuilds the double model from the f32/double table layout {fir, real {eps, c}, pair {e_r, p_i, g, cr, ci}}.
DiscreteModel model_from_tables(const nlohmann::json& j, double fs) {
  DiscreteModel m;
  m.fs_hz = fs;
  for (const auto& v : j.at("fir")) m.fir.push_back(v.get<double>());
  for (const auto& v : j.at("real")) {
    RealTerm t;
    t.eps = v.at(0).get<double>();
    t.c = v.at(1).get<double>();
    t.lambda = -std::log1p(-t.eps) * fs;
    m.real.push_back(t);
  }
  for (const auto& v : j.at("pair")) {
    PairTerm t;
    t.e_r = v.at(0).get<double>();
    t.p_i = v.at(1).get<double>();
    t.g = v.at(2).get<double>();
    t.c = {0.5 * v.at(3).get<double>(), -0.5 * v.at(4).get<double>()};
    t.alpha = -std::log(std::hypot(1.0 + t.e_r, t.p_i)) * fs;
    t.beta = -std::atan2(t.p_i, 1.0 + t.e_r) * fs;
    m.pair.push_back(t);
  }
  return m;
}

/// An integer of the block in [lo, hi], range-checked before conversion (a JSON float or an out-of-range
/// value would make the conversion undefined).
std::int32_t block_integer(const nlohmann::json& v, const std::string& what, long long lo, long long hi,
                           const std::string& origin) {
  if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi ||
      (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(hi)))
    throw InputError(fmt::format("{}: admitgen:model block: {} must be an integer in [{}, {}] (value {})", origin, what,
                                 lo, hi, v.dump()));
  return static_cast<std::int32_t>(v.get<long long>());
}

/// The q31/q15 tables of one rate, within the bounds the runtime enforces at init (docs/runtime.md, "Limits
/// and misuse": it would refuse the model with ADMITGEN_RT_BAD_MODEL).
FixedCoefficients fixed_from_tables(const nlohmann::json& coeffs, Format format, const std::string& origin) {
  const auto integer = [&origin](const nlohmann::json& v, const std::string& what, long long lo, long long hi) {
    return block_integer(v, what, lo, hi, origin);
  };
  FixedCoefficients q;
  q.format = format;
  // q15 tables hold 16-bit coefficients (B = 15) or 32-bit ones (B = 31; codegen/coefficients.hpp, wide()).
  const bool wide = format == Format::q15 && coeffs.at("bits").is_number_integer() && coeffs.at("bits").get<long long>() == 31;
  const int bits = coefficient_bits(format, wide);
  const long long m_max = (1LL << bits) - 1, m_min = -(1LL << bits);  // mantissas: int32 or int16
  q.bits = integer(coeffs.at("bits"), "bits", bits, bits);
  q.out_shift = integer(coeffs.at("out_shift"), "out_shift", -62, 62);
  q.y_exp = integer(coeffs.at("y_exp"), "y_exp", -62, 62);
  q.acc_shift = integer(coeffs.at("acc_shift"), "acc_shift", 1, 62);
  q.l1_norm = coeffs.at("l1_norm").get<double>();
  for (const auto& v : coeffs.at("fir")) q.fir.push_back(integer(v, "a fir mantissa", m_min, m_max));
  for (const auto& t : coeffs.at("real"))
    q.real.push_back({integer(t.at(0), "a real pole's eps", m_min, m_max),
                      integer(t.at(1), "a real pole's shift", 1 - bits, 62 - bits),
                      integer(t.at(2), "a real pole's c", m_min, m_max)});
  for (const auto& t : coeffs.at("pair")) {
    q.pair.push_back({integer(t.at(0), "a pair's e_r", m_min, m_max), integer(t.at(1), "a pair's p_i", m_min, m_max),
                      integer(t.at(2), "a pair's g", m_min, m_max),
                      integer(t.at(3), "a pair's shift", 1 - bits, 62 - bits),
                      integer(t.at(4), "a pair's c_r", m_min, m_max), integer(t.at(5), "a pair's c_i", m_min, m_max)});
    const auto& p = q.pair.back();
    if (std::abs(std::int64_t{p.e_r}) + std::abs(std::int64_t{p.p_i}) + std::abs(std::int64_t{p.g}) > (1LL << 31))
      throw InputError(fmt::format("{}: admitgen:model block: pair {} has |e_r| + |p_i| + |g| > 2^31 (its 64-bit "
                                   "update sum could overflow)", origin, q.pair.size()));
  }
  std::int64_t output_sum = 0;
  for (const auto d : q.fir) output_sum += std::abs(std::int64_t{d});
  for (const auto& t : q.real) output_sum += std::abs(std::int64_t{t.c});
  for (const auto& t : q.pair) output_sum += std::abs(std::int64_t{t.c_r}) + std::abs(std::int64_t{t.c_i});
  if (output_sum > (1LL << 31))
    throw InputError(fmt::format("{}: admitgen:model block: the output table's sum of |mantissa| exceeds 2^31 (the "
                                 "64-bit accumulator could overflow)", origin));
  return q;
}

EmittedHeader header_from_block(const nlohmann::json& j, const std::string& origin) {
  if (!j.is_object() || !j.contains("schema") || j.at("schema") != kModelBlockSchema)
    throw InputError(fmt::format("{}: admitgen:model block: schema {} (this admitgen reads {})", origin,
                                 j.is_object() && j.contains("schema") ? j.at("schema").dump() : "missing",
                                 kModelBlockSchema));
  EmittedHeader h;
  h.format = codegen::parse_format(j.at("format").get<std::string>());
  h.name = j.at("name").get<std::string>();
  const auto order = Order::parse(j.at("order").get<std::string>());
  const auto theta = j.at("continuous").at("theta").get<std::vector<double>>();
  if (theta.size() != static_cast<std::size_t>(order.dim()))
    throw InputError(fmt::format("{}: admitgen:model block: continuous theta has {} values, order {} needs {}", origin,
                                 theta.size(), order.name(), order.dim()));
  h.surface = MultipoleSurface{order, Eigen::Map<const Eigen::VectorXd>(theta.data(), Eigen::Index(theta.size()))};
  h.data_f_min_hz = j.at("data_f_min_hz").get<double>();
  h.data_f_max_hz = j.at("data_f_max_hz").get<double>();
  for (const auto& r : j.at("rates")) {
    EmittedHeader::Rate rate;
    rate.fs_hz = block_integer(r.at("fs_hz"), "fs_hz", 1000, 1000000, origin);
    const auto& coeffs = r.at(format_name(h.format));
    if (h.format == Format::f32) {
      rate.model = model_from_tables(coeffs, rate.fs_hz);
    } else {
      rate.fixed = fixed_from_tables(coeffs, h.format, origin);
      rate.model = rate.fixed->dequantised(rate.fs_hz);
    }
    h.rates.push_back(std::move(rate));
  }
  return h;
}

}  // namespace

std::string model_block(const codegen::Emission& emission) { return emission_json(emission).dump(); }

std::string header_text(const codegen::Emission& emission, const std::string& template_text,
                        const std::string& file_name) {
  return codegen::render_header(emission, template_text, file_name, model_block(emission));
}

EmittedHeader read_emitted_header(const std::string& text, const std::string& origin) {
  const std::string begin = "admitgen:model", end = "admitgen:end";
  const std::size_t b = text.find(begin), x = text.find(end);
  if (b == std::string::npos || x == std::string::npos || x < b)
    throw InputError(fmt::format("{}: no admitgen:model block (not a header written by admitgen emit)", origin));
  try {
    return header_from_block(nlohmann::json::parse(text.substr(b + begin.size(), x - b - begin.size())), origin);
  } catch (const nlohmann::json::exception& ex) {
    throw InputError(fmt::format("{}: unreadable admitgen:model block ({})", origin, ex.what()));
  }
}

}  // namespace admitgen::io

// SPDX-License-Identifier: MIT
#include "codegen/emission.hpp"

#include "codegen/runtime_filter.hpp"
#include "codegen/template_text.hpp"
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "core/version.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>

namespace admitgen::codegen {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// A C double literal that reads back to exactly `v` (shortest round-trip digits, always '.' or 'e').
std::string dlit(double v) {
  ADMITGEN_ENSURE(std::isfinite(v), "non-finite coefficient {}", v);
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}
/// The same for float (shortest digits of the float, 'f' suffix).
std::string flit(float v) {
  ADMITGEN_ENSURE(std::isfinite(v), "non-finite coefficient {}", v);
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + "f";
}

std::string join(const std::vector<std::string>& parts, const char* sep) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : sep) + p;
  return s;
}

std::vector<double> data_frequencies(const FitRecord& fit) {
  if (fit.predictive && !fit.predictive->f_hz.empty()) return fit.predictive->f_hz;
  // Older fits: log-spaced points over the data range (what the refit needs is the band, not the grid).
  std::vector<double> f;
  const double lo = fit.input.f_min_hz, hi = fit.input.f_max_hz;
  const auto n = static_cast<int>(std::max<std::int64_t>(16, fit.input.points));
  for (int i = 0; i < n; ++i) f.push_back(lo * std::pow(hi / lo, double(i) / (n - 1)));
  return f;
}

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

TemplateContext item(std::map<std::string, std::string> values) { return TemplateContext{std::move(values), {}}; }

/// One-item list when `empty` (C has no empty arrays: a zero pad entry), else no items.
std::vector<TemplateContext> pad_if(bool empty) {
  return empty ? std::vector<TemplateContext>{item({})} : std::vector<TemplateContext>{};
}

std::string real_note(const RealTerm& r, double fs) {
  return fmt::format("lambda = {:.6g} 1/s ({:.6g} Hz), lambda T = {:.4g}", r.lambda, r.lambda / (2 * kPi), r.lambda / fs);
}
std::string pair_note(const PairTerm& p, double fs) {
  return fmt::format("alpha = {:.6g}, beta = {:.6g} 1/s ({:.6g} Hz), alpha T = {:.4g}", p.alpha, p.beta,
                     p.beta / (2 * kPi), p.alpha / fs);
}

/// The C text of one table row (width entries from `row`).
template <typename T, typename Print>
std::string row_text(const T* row, std::size_t width, Print print) {
  std::vector<std::string> v;
  for (std::size_t j = 0; j < width; ++j) v.push_back(print(row[j]));
  return join(v, ", ");
}

/// The emitted tables of one rate in the runtime's layout (runtime_filter.hpp), their entries as C text.
struct TableText {
  std::vector<std::string> fir, real, pair;  ///< fir: one entry per tap; real, pair: one row per term
  std::size_t real_width = 0, pair_width = 0;
};

template <typename Model, typename Print>
TableText table_text(const Model& tables, std::size_t real_width, std::size_t pair_width, Print print) {
  TableText t;
  t.real_width = real_width;
  t.pair_width = pair_width;
  for (const auto v : tables.fir()) t.fir.push_back(print(v));
  for (std::size_t j = 0; j < tables.real().size(); j += real_width) t.real.push_back(row_text(&tables.real()[j], real_width, print));
  for (std::size_t j = 0; j < tables.pair().size(); j += pair_width) t.pair.push_back(row_text(&tables.pair()[j], pair_width, print));
  return t;
}

TableText emitted_tables(const EmittedRate& r, Format format) {
  const auto integer = [](auto v) { return std::to_string(v); };
  switch (format) {
    case Format::f32:
      return table_text(RuntimeModelF32(r.f32, r.fs_hz), ADMITGEN_RT_F32_REAL_WIDTH, ADMITGEN_RT_F32_PAIR_WIDTH, flit);
    case Format::q31:
      return table_text(RuntimeModelQ31(*r.fixed, r.fs_hz), ADMITGEN_RT_Q_REAL_WIDTH, ADMITGEN_RT_Q_PAIR_WIDTH, integer);
    case Format::q15:  // 32-bit coefficients: the q31 rows
      return r.fixed->wide()
                 ? table_text(RuntimeModelQ31(*r.fixed, r.fs_hz), ADMITGEN_RT_Q_REAL_WIDTH, ADMITGEN_RT_Q_PAIR_WIDTH, integer)
                 : table_text(RuntimeModelQ15(*r.fixed, r.fs_hz), ADMITGEN_RT_Q_REAL_WIDTH, ADMITGEN_RT_Q_PAIR_WIDTH, integer);
  }
  throw InternalError("unknown format");
}

/// The double-precision reference tables, in the f32 layout (RuntimeModelF32 rows, double entries).
TableText reference_tables(const DiscreteModel& m) {
  TableText t;
  t.real_width = ADMITGEN_RT_F32_REAL_WIDTH;
  t.pair_width = ADMITGEN_RT_F32_PAIR_WIDTH;
  for (const double d : m.fir) t.fir.push_back(dlit(d));
  for (const auto& r : m.real) {
    std::array<double, ADMITGEN_RT_F32_REAL_WIDTH> row{};
    row[ADMITGEN_RT_F32_REAL_EPS] = r.eps;
    row[ADMITGEN_RT_F32_REAL_C] = r.c;
    t.real.push_back(row_text(row.data(), row.size(), dlit));
  }
  for (const auto& p : m.pair) {
    std::array<double, ADMITGEN_RT_F32_PAIR_WIDTH> row{};
    row[ADMITGEN_RT_F32_PAIR_ER] = p.e_r;
    row[ADMITGEN_RT_F32_PAIR_PI] = p.p_i;
    row[ADMITGEN_RT_F32_PAIR_G] = p.g;
    row[ADMITGEN_RT_F32_PAIR_CR] = 2.0 * p.c.real();
    row[ADMITGEN_RT_F32_PAIR_CI] = -2.0 * p.c.imag();
    t.pair.push_back(row_text(row.data(), row.size(), dlit));
  }
  return t;
}

/// Rows of the f32 / fixed / reference tables of one rate, as template lists.
void table_lists(const EmittedRate& r, Format format, TemplateContext& c) {
  const auto& m = r.model;
  const TableText emitted = emitted_tables(r, format), ref = reference_tables(m);
  std::vector<TemplateContext> fir, real, pair, ref_fir, ref_real, ref_pair;
  for (std::size_t k = 0; k < m.fir.size(); ++k) {
    fir.push_back(item({{"v", emitted.fir[k]}, {"k", std::to_string(k)}}));
    ref_fir.push_back(item({{"v", ref.fir[k]}, {"k", std::to_string(k)}}));
  }
  for (std::size_t q = 0; q < m.real.size(); ++q) {
    real.push_back(item({{"v", emitted.real[q]}, {"note", real_note(m.real[q], r.fs_hz)}}));
    ref_real.push_back(item({{"v", ref.real[q]}}));
  }
  for (std::size_t s = 0; s < m.pair.size(); ++s) {
    pair.push_back(item({{"v", emitted.pair[s]}, {"note", pair_note(m.pair[s], r.fs_hz)}}));
    ref_pair.push_back(item({{"v", ref.pair[s]}}));
  }
  c.values["fir_len"] = std::to_string(std::max<std::size_t>(1, m.fir.size()));
  c.values["real_len"] = std::to_string(std::max<std::size_t>(1, emitted.real_width * m.real.size()));
  c.values["pair_len"] = std::to_string(std::max<std::size_t>(1, emitted.pair_width * m.pair.size()));
  c.values["ref_real_len"] = std::to_string(std::max<std::size_t>(1, ref.real_width * m.real.size()));
  c.values["ref_pair_len"] = std::to_string(std::max<std::size_t>(1, ref.pair_width * m.pair.size()));
  c.lists["fir"] = fir;
  c.lists["real"] = real;
  c.lists["pair"] = pair;
  c.lists["ref_fir"] = ref_fir;
  c.lists["ref_real"] = ref_real;
  c.lists["ref_pair"] = ref_pair;
  c.lists["pad_fir"] = pad_if(m.fir.empty());
  c.lists["pad_real"] = pad_if(m.real.empty());
  c.lists["pad_pair"] = pad_if(m.pair.empty());
}

TemplateContext rate_context(const EmittedRate& r, Format format) {
  TemplateContext c;
  const auto& m = r.model;
  c.values["fs"] = std::to_string(r.fs_hz);
  c.values["refit_err"] = fmt::format("{:.3g}", m.refit_max_rel_error);
  c.values["plrc_err"] = fmt::format("{:.3g}", m.plrc_max_rel_error);
  const Fidelity& fi = r.fidelity;
  c.values["fidelity"] = fmt::format(
      "max |H - G|/|G| of the {} coefficients as the kernel runs them: {:.3g} in the data band (at {:.5g} Hz), "
      "{:.3g} from its top to 0.45 fs; rounding noise floor {:.3g} for |u| <= 1 (a full-scale tone: SNR >= {:.1f} dB "
      "in band, at {:.5g} Hz)",
      format_name(format), fi.max_rel_deviation, fi.at_hz, fi.max_rel_deviation_above, fi.noise_floor, fi.min_snr_db,
      fi.snr_at_hz);
  c.values["passive_note"] =
      !m.passive_certified ? "not certified by the generator (see admitgen check)"
      : m.passive_rounds == 0 ? "Re H >= 0 up to Nyquist (Hamiltonian test, docs/passivity.md); the least-squares refit was already passive"
                              : fmt::format("Re H >= 0 up to Nyquist (Hamiltonian test, docs/passivity.md); refit constrained to "
                                            "Re H >= 0, {} constraint round(s)", m.passive_rounds);
  c.values["n_fir"] = std::to_string(m.fir.size());
  c.values["n_real"] = std::to_string(m.real.size());
  c.values["n_pair"] = std::to_string(m.pair.size());
  c.values["folded"] = m.folded.empty() ? "none" : join(m.folded, "; ");
  c.values["tail"] = std::to_string(m.tail_samples(6.0));
  c.values["ref_h0"] = dlit(m.h0());
  if (format == Format::f32) {
    c.values["l1"] = fmt::format("{:.6g}", m.l1_norm());
    c.lists["f32_model"] = {item({{"h0", flit(r.f32.h0)}})};
    c.lists["fixed_doc"] = {};
  } else {
    const auto& q = *r.fixed;
    c.values["l1"] = fmt::format("{:.6g}", q.l1_norm);
    c.lists["f32_model"] = {};
    c.lists["fixed_doc"] = {item({{"out_shift", std::to_string(q.out_shift)},
                                  {"y_exp", std::to_string(q.y_exp)},
                                  {"acc_shift", std::to_string(q.acc_shift)},
                                  {"decay", std::to_string(q.zero_decay_bound())}})};
  }
  table_lists(r, format, c);
  // The struct's table pointers: 16-bit (or f32/q31) tables in fir/real/pair; q15 with 32-bit coefficients in
  // fir32/real32/pair32 (runtime/include/admitgen_rt.h).
  const bool wide = r.fixed && r.fixed->wide();
  c.lists["tables16"] = pad_if(!wide);
  c.lists["q15_no_tables32"] = pad_if(format == Format::q15 && !wide);
  c.lists["q15_tables32"] = pad_if(wide);
  return c;
}

std::vector<TemplateContext> band_rows(const std::vector<BandAbsorption>& bands) {
  std::vector<TemplateContext> rows;
  for (const auto& b : bands)
    rows.push_back(item({{"v", fmt::format("{}, {}, {}", flit(static_cast<float>(b.center_hz)),
                                           flit(static_cast<float>(b.alpha_normal)),
                                           flit(static_cast<float>(b.alpha_random)))},
                         {"note", fmt::format("{:.0f}-{:.0f} Hz{}", b.lo_hz, b.hi_hz,
                                              b.in_data ? "" : ", outside the data: model extrapolation")}}));
  return rows;
}

/// Rates integral in [1 kHz, 1 MHz] and distinct; the name a C identifier.
void validate(const EmitSettings& settings) {
  if (!std::regex_match(settings.name, std::regex("[A-Za-z_][A-Za-z0-9_]{0,63}")))
    throw InputError(fmt::format("{} is not a C identifier (letters, digits, '_'; not starting with a digit)",
                                 setting("name", "'" + settings.name + "'")));
  if (settings.fs_hz.empty()) throw InputError("at least one " + setting("fs_hz") + " is required");
  std::set<int> seen;
  for (double fs : settings.fs_hz) {
    if (!(fs >= 1000.0 && fs <= 1e6) || fs != std::floor(fs))
      throw InputError(fmt::format("{}: sample rates must be whole numbers of Hz in [1000, 1000000]",
                                   setting("fs_hz", fmt::format("{:g}", fs))));
    if (!seen.insert(static_cast<int>(fs)).second)
      throw InputError(fmt::format("{} is given twice", setting("fs_hz", fmt::format("{:g}", fs))));
  }
}

}  // namespace

EmissionSource read_emission_source(const FitRecord& fit, const std::string& fit_path, const EmitSettings& settings) {
  EmissionSource e;
  e.estimate = settings.estimate;
  e.surface = multipole_from_fit(fit, settings.order, settings.estimate, fit_path);
  e.fit_version = fit.version;
  e.input_sha256 = fit.input.sha256;
  e.seed = fit.settings.seed;
  e.data_f_hz = data_frequencies(fit);
  const std::size_t slash = fit_path.find_last_of('/');
  e.fit_name = slash == std::string::npos ? fit_path : fit_path.substr(slash + 1);
  return e;
}

DiscreteModel EmittedRate::emitted_model() const { return fixed ? fixed->dequantised(fs_hz) : as_emitted(model, f32); }

Emission prepare_emission(const EmissionSource& source, const EmitSettings& settings) {
  validate(settings);
  Emission e;
  static_cast<EmissionSource&>(e) = source;
  e.settings = settings;
  DiscretiseOptions options;
  options.fir_taps = settings.fir_taps;
  options.passivity_violations = settings.passivity_violations;
  options.passive_margin = settings.passive_margin;
  if (settings.refit_to_stored_poles)
    options.store_poles = [format = settings.format, wide = settings.wide_coefficients](DiscreteModel& m) {
      store_poles(m, format, wide);
    };
  for (double fs : settings.fs_hz) {
    EmittedRate r;
    r.fs_hz = static_cast<int>(fs);
    r.model = discretise(e.surface.order, e.surface.theta, fs, e.data_f_hz, options);
    r.f32 = to_float(r.model);
    if (settings.format != Format::f32) r.fixed = quantise(r.model, settings.format, settings.wide_coefficients);
    e.rates.push_back(std::move(r));
  }
  const auto [lo, hi] = std::minmax_element(e.data_f_hz.begin(), e.data_f_hz.end());
  for (auto& r : e.rates)
    r.fidelity = fidelity(e.surface, r.emitted_model(), r.fixed ? &*r.fixed : nullptr, *lo, *hi);
  e.octave = band_absorption(e.surface.order, e.surface.theta, 1, *lo, *hi);
  e.third_octave = band_absorption(e.surface.order, e.surface.theta, 3, *lo, *hi);
  return e;
}

Emission prepare_emission(const FitRecord& fit, const std::string& fit_path, const EmitSettings& settings) {
  validate(settings);
  return prepare_emission(read_emission_source(fit, fit_path, settings), settings);
}

std::string render_header(const Emission& e, const std::string& template_text, const std::string& file_name,
                          const std::string& model_block) {
  TemplateContext c;
  const auto& s = e.settings;
  const std::string fmt_name = format_name(s.format);
  std::vector<std::string> rate_list;
  for (const auto& r : e.rates) rate_list.push_back(std::to_string(r.fs_hz));
  c.values = {{"file", file_name},
              {"version", kVersion},
              {"fit_name", e.fit_name},
              {"format", fmt_name},
              {"FORMAT", upper(fmt_name)},
              {"name", s.name},
              {"NAME", upper(s.name)},
              {"estimate_key", estimate_name(s.estimate)},
              {"fir_taps", std::to_string(s.fir_taps)},
              {"input_sha256", e.input_sha256},
              {"order", e.surface.order.name()},
              {"estimate", e.estimate == Estimate::passive ? "passive estimate: best sample's poles, residues refitted under Re G >= 0"
                           : e.estimate == Estimate::mean ? "posterior mean" : "highest-likelihood sample"},
              {"seed", std::to_string(e.seed)},
              {"fit_version", e.fit_version},
              {"points", std::to_string(e.data_f_hz.size())},
              {"f_min", fmt::format("{:g}", *std::min_element(e.data_f_hz.begin(), e.data_f_hz.end()))},
              {"f_max", fmt::format("{:g}", *std::max_element(e.data_f_hz.begin(), e.data_f_hz.end()))},
              {"rate_list", join(rate_list, ", ")},
              {"abi", std::to_string(kRuntimeAbi)},
              {"ctype", table_ctype(s.format, s.wide_coefficients)},
              {"n_theta", std::to_string(e.surface.theta.size())},
              {"n_octave", std::to_string(e.octave.size())},
              {"n_third", std::to_string(e.third_octave.size())},
              {"bits_doc", std::to_string(coefficient_bits(s.format, s.wide_coefficients))},
              {"data_bits", s.format == Format::q15 ? "15" : "31"},
              {"coefficient_note",
               s.format == Format::q15 && s.wide_coefficients
                   ? "32-bit (int32 tables in fir32/real32/pair32, B = 31): chosen because the 16-bit coefficients did "
                     "not pass admitgen check (the reason is in the notes above)"
                   : fmt::format("{}-bit mantissas, B = {}", coefficient_bits(s.format, s.wide_coefficients) + 1,
                                 coefficient_bits(s.format, s.wide_coefficients))},
              {"order_q", std::to_string(e.surface.order.q())},
              {"order_s", std::to_string(e.surface.order.s())}};
  std::string json = model_block;
  for (std::size_t p = 0; (p = json.find("*/", p)) != std::string::npos;) json.replace(p, 2, "*\\/");
  c.values["model_json"] = json;
  const auto names = e.surface.order.parameter_names();
  for (Eigen::Index i = 0; i < e.surface.theta.size(); ++i)
    c.lists["params"].push_back(item({{"pname", names[static_cast<std::size_t>(i)]}, {"pvalue", dlit(e.surface.theta[i])},
                                      {"last", i + 1 == e.surface.theta.size() ? "" : ","}}));
  for (const auto& r : e.rates) c.lists["rates"].push_back(rate_context(r, s.format));
  c.lists["notes"] = {};
  for (const auto& n : e.notes) c.lists["notes"].push_back(item({{"text", plain_settings(n)}}));
  // The settings that differ from emit's defaults, for the command that regenerates the header (the
  // template spells them as the command line's options).
  c.lists["order_chosen"] = pad_if(!s.order.empty());
  c.lists["estimate_chosen"] = pad_if(s.estimate != Estimate::passive);
  c.lists["fir_taps_chosen"] = pad_if(s.fir_taps > 0);
  c.lists["enforcement_off"] = pad_if(!s.enforce_passivity);
  c.lists["is_f32"] = pad_if(s.format == Format::f32);
  c.lists["is_fixed"] = pad_if(s.format != Format::f32);
  c.lists["octave"] = band_rows(e.octave);
  c.lists["third"] = band_rows(e.third_octave);
  return render_template(template_text, c);
}

std::string golden_vectors(const Emission& e, std::uint64_t seed) {
  if (e.settings.format == Format::f32)
    throw InputError("golden vectors need " + setting("format") + " q31 or q15 (f32 is not bit-exact)");
  const EmittedRate& r = e.rates.front();
  const FixedCoefficients& q = *r.fixed;
  const std::int32_t full = q.format == Format::q31 ? INT32_MAX : INT16_MAX;
  std::vector<std::int32_t> in;
  in.push_back(full);  // impulse
  in.resize(256, 0);
  const auto h = q.dequantised(r.fs_hz).impulse_response(256);
  for (int n = 0; n < 256; ++n) in.push_back(h[static_cast<std::size_t>(255 - n)] >= 0.0 ? full : -full - 1);
  Rng rng(seed);
  for (int n = 0; n < 512; ++n)
    in.push_back(static_cast<std::int32_t>(std::floor((rng.uniform() - 0.5) * (double(full) + 1.0))));
  in.resize(in.size() + 256, 0);
  const auto out = run_runtime(q, r.fs_hz, in);
  std::string s = fmt::format(
      "# admitgen golden vectors (bit-exact), format {}, fs {} Hz, model {} ({}), admitgen {}\n"
      "# fit input sha256 {}, noise seed {}\n"
      "# segments: [0,256) full-scale impulse; [256,512) full-scale worst-case sign of h; [512,1024) uniform noise "
      "at -6 dBFS (admitgen::Rng xoshiro256** seed {}); [1024,1280) zeros\n"
      "# count, then per sample: input output (decimal) # hex\n{}\n",
      format_name(q.format), r.fs_hz, e.settings.name, e.surface.order.name(), kVersion, e.input_sha256, seed, seed,
      in.size());
  for (std::size_t n = 0; n < in.size(); ++n)
    s += fmt::format("{} {} # {:08x} {:08x}\n", in[n], out[n], static_cast<std::uint32_t>(in[n]),
                     static_cast<std::uint32_t>(out[n]));
  return s;
}

}  // namespace admitgen::codegen

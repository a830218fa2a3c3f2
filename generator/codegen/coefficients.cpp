// SPDX-License-Identifier: MIT
#include "codegen/coefficients.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen::codegen {
namespace {

std::int32_t round_to_int(double v, int bits) {
  const double r = std::nearbyint(v);
  const double lim = std::ldexp(1.0, bits);
  ADMITGEN_ENSURE(std::abs(r) < lim, "mantissa {} exceeds {} bits", r, bits);
  return static_cast<std::int32_t>(r);
}

}  // namespace

Format parse_format(const std::string& text) {
  if (text == "f32") return Format::f32;
  if (text == "q31") return Format::q31;
  if (text == "q15") return Format::q15;
  throw InputError(fmt::format("unknown format '{}' (expected f32, q31 or q15)", text));
}

const char* format_name(Format format) {
  switch (format) {
    case Format::f32: return "f32";
    case Format::q31: return "q31";
    case Format::q15: return "q15";
  }
  return "?";
}

FloatCoefficients to_float(const DiscreteModel& m) {
  FloatCoefficients f;
  for (double d : m.fir) f.fir.push_back(static_cast<float>(d));
  for (const auto& r : m.real) f.real.push_back({static_cast<float>(r.eps), static_cast<float>(r.c)});
  for (const auto& p : m.pair)
    f.pair.push_back({static_cast<float>(p.e_r), static_cast<float>(p.p_i), static_cast<float>(p.g),
                      static_cast<float>(2.0 * p.c.real()), static_cast<float>(-2.0 * p.c.imag())});
  // h0 from the float values actually emitted, so y = h0·u + s holds for the float tables.
  double h0 = f.fir.empty() ? 0.0 : f.fir[0];
  for (const auto& r : f.real) h0 += double(r[0]) * double(r[1]);
  for (const auto& p : f.pair) h0 += double(p[3]) * double(p[2]);
  f.h0 = static_cast<float>(h0);
  return f;
}

DiscreteModel as_emitted(const DiscreteModel& model, const FloatCoefficients& f) {
  DiscreteModel m = model;
  for (std::size_t k = 0; k < m.fir.size(); ++k) m.fir[k] = f.fir[k];
  for (std::size_t q = 0; q < m.real.size(); ++q) {
    m.real[q].eps = f.real[q][0];
    m.real[q].c = f.real[q][1];
  }
  for (std::size_t s = 0; s < m.pair.size(); ++s) {  // {e_r, p_i, g, 2 Re c, −2 Im c}
    m.pair[s].e_r = f.pair[s][0];
    m.pair[s].p_i = f.pair[s][1];
    m.pair[s].g = f.pair[s][2];
    m.pair[s].c = {0.5 * f.pair[s][3], -0.5 * f.pair[s][4]};
  }
  return m;
}

namespace {

/// Per-term exponent: the largest shift with the (sum of the n) mantissas inside 2^B minus rounding room.
int term_shift(double magnitude_sum, int n, int b) {
  const double full = std::ldexp(1.0, b);
  int s = -4;
  while (s < 62 - b && magnitude_sum * std::ldexp(1.0, b + s + 1) <= full - n - 1) ++s;
  return s;
}

/// A real term's pole in B fraction bits (output coefficient left 0).
FixedCoefficients::Real quantise_pole(const RealTerm& r, int b) {
  FixedCoefficients::Real t{};
  t.shift = term_shift(r.eps, 1, b);
  ADMITGEN_ENSURE(t.shift >= 0, "eps {} must be below 1", r.eps);
  t.eps = std::max<std::int32_t>(1, round_to_int(std::ldexp(r.eps, b + t.shift), b));
  return t;
}

/// A pair's pole and input gain in B fraction bits (output coefficients left 0).
FixedCoefficients::Pair quantise_pole(const PairTerm& p, int b) {
  FixedCoefficients::Pair t{};
  t.shift = term_shift(std::abs(p.e_r) + std::abs(p.p_i) + p.g, 3, b);
  t.e_r = round_to_int(std::ldexp(p.e_r, b + t.shift), b);
  t.p_i = round_to_int(std::ldexp(p.p_i, b + t.shift), b);
  t.g = round_to_int(std::ldexp(p.g, b + t.shift), b);
  // Each state's L1 norm is at most g/(1 − |π|), 1 in exact arithmetic (g = 1 − |π|), and reaches it when β = 0.
  // Rounded independently, g can exceed the stored pole's 1 − |π| by a fraction of an LSB; a full-scale input
  // then saturates the state (headroom). Where the stored pair's state L1 norm (state_l1) exceeds 1, g is lowered
  // to the stored pole's 1 − |π| (rounded down), which bounds both norms by 1 (a relative gain change of the size
  // of the excess, which the fidelity check measures).
  const double s = std::ldexp(1.0, -(b + t.shift));
  PairTerm stored;
  stored.e_r = t.e_r * s, stored.p_i = t.p_i * s, stored.g = t.g * s;
  if (const auto [xi, eta] = state_l1(stored); std::max(xi, eta) > 1.0) {
    const double room = 1.0 - std::hypot(1.0 + stored.e_r, stored.p_i);
    t.g = std::min<std::int32_t>(t.g, static_cast<std::int32_t>(std::floor(std::ldexp(room, b + t.shift))));
  }
  return t;
}

void set_pair_rates(PairTerm& t, double fs_hz) {
  t.alpha = -std::log(std::hypot(1.0 + t.e_r, t.p_i)) * fs_hz;
  t.beta = -std::atan2(t.p_i, 1.0 + t.e_r) * fs_hz;
}

}  // namespace

int data_bits(Format format) { return format == Format::q15 ? 15 : 31; }

double FixedCoefficients::output_gain() const {
  return std::ldexp(1.0, bits + 31 - data_bits(format) + out_shift - y_exp - acc_shift);
}

int coefficient_bits(Format format, bool wide) { return format == Format::q15 && !wide ? 15 : 31; }

const char* table_ctype(Format format, bool wide) {
  return format == Format::f32 ? "float" : coefficient_bits(format, wide) == 31 ? "int32_t" : "int16_t";
}

void store_poles(DiscreteModel& m, Format format, bool wide) {
  const auto to_f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  const int b = coefficient_bits(format, wide);
  for (auto& r : m.real) {
    if (format == Format::f32) {
      r.eps = to_f(r.eps);
    } else {
      const auto t = quantise_pole(r, b);
      r.eps = std::ldexp(double(t.eps), -(b + t.shift));
    }
    r.lambda = -std::log1p(-r.eps) * m.fs_hz;
  }
  for (auto& p : m.pair) {
    if (format == Format::f32) {
      p.e_r = to_f(p.e_r), p.p_i = to_f(p.p_i), p.g = to_f(p.g);
    } else {
      const auto t = quantise_pole(p, b);
      const double s = std::ldexp(1.0, -(b + t.shift));
      p.e_r = t.e_r * s, p.p_i = t.p_i * s, p.g = t.g * s;
    }
    set_pair_rates(p, m.fs_hz);
  }
}

FixedCoefficients quantise(const DiscreteModel& m, Format format, bool wide) {
  ADMITGEN_ENSURE(format != Format::f32, "quantise() is for q31/q15");
  FixedCoefficients q;
  q.format = format;
  q.bits = coefficient_bits(format, wide);
  const int b = q.bits;
  const double full = std::ldexp(1.0, b);

  for (const auto& r : m.real) q.real.push_back(quantise_pole(r, b));
  for (const auto& p : m.pair) q.pair.push_back(quantise_pole(p, b));

  // Output table: one exponent from the sum of magnitudes.
  std::vector<double> out;
  for (double d : m.fir) out.push_back(d);
  for (const auto& r : m.real) out.push_back(r.c);
  for (const auto& p : m.pair) {
    out.push_back(2.0 * p.c.real());
    out.push_back(-2.0 * p.c.imag());
  }
  double sum = 0.0;
  for (double v : out) sum += std::abs(v);
  const int n_out = static_cast<int>(out.size());
  q.y_exp = -30;
  while (sum * std::ldexp(1.0, b - q.y_exp) > full - n_out - 1) ++q.y_exp;
  std::vector<std::int32_t> mant;
  for (double v : out) mant.push_back(round_to_int(std::ldexp(v, b - q.y_exp), b));
  std::size_t j = 0;
  for (std::size_t k = 0; k < m.fir.size(); ++k) q.fir.push_back(mant[j++]);
  for (auto& r : q.real) r.c = mant[j++];
  for (auto& p : q.pair) {
    p.c_r = mant[j++];
    p.c_i = mant[j++];
  }

  q.l1_norm = q.dequantised(m.fs_hz).l1_norm();
  // 2^out_shift ≥ ‖h‖₁ (1 + 2^-10): the 2^-10 margin covers the state rounding (< 1 LSB per state).
  q.out_shift = std::max(0, static_cast<int>(std::ceil(std::log2(q.l1_norm * (1.0 + 1.0 / 1024.0)))));
  q.acc_shift = q.bits + 31 - data_bits(format) + q.out_shift - q.y_exp;
  ADMITGEN_ENSURE(q.acc_shift >= 1 && q.acc_shift <= 62, "output shift {} out of range", q.acc_shift);
  return q;
}

DiscreteModel FixedCoefficients::dequantised(double fs_hz) const {
  DiscreteModel d;
  d.fs_hz = fs_hz;
  const double ys = std::ldexp(1.0, y_exp - bits);
  for (auto v : fir) d.fir.push_back(v * ys);
  for (const auto& r : real) {
    RealTerm t;
    t.eps = std::ldexp(double(r.eps), -(bits + r.shift));
    t.lambda = -std::log1p(-t.eps) * fs_hz;
    t.c = r.c * ys;
    d.real.push_back(t);
  }
  for (const auto& p : pair) {
    PairTerm t;
    const double s = std::ldexp(1.0, -(bits + p.shift));
    t.e_r = p.e_r * s;
    t.p_i = p.p_i * s;
    t.g = p.g * s;
    set_pair_rates(t, fs_hz);
    t.c = {0.5 * p.c_r * ys, -0.5 * p.c_i * ys};
    d.pair.push_back(t);
  }
  return d;
}

int FixedCoefficients::zero_decay_bound() const {
  // |state_n| ≤ r^n · 2^31.5 (a pair's |ψ| ≤ √2 · 2^31); 0 once below 1 LSB.
  const DiscreteModel d = dequantised(1.0);
  double slowest = std::numeric_limits<double>::infinity();
  for (const auto& r : d.real) slowest = std::min(slowest, -std::log1p(-r.eps));
  for (const auto& p : d.pair) slowest = std::min(slowest, -std::log(std::hypot(1.0 + p.e_r, p.p_i)));
  const double n = std::isinf(slowest) ? 0.0 : 31.5 * std::log(2.0) / slowest;
  return static_cast<int>(std::ceil(n)) + static_cast<int>(fir.size()) + 1;
}

}  // namespace admitgen::codegen

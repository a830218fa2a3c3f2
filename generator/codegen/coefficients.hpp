// SPDX-License-Identifier: MIT
/// @file
/// The coefficients actually emitted for one sample rate and format: the float tables, and the fixed-point
/// quantisation (per-term exponents, one output exponent, output scaling) whose representation, bounds and
/// rounding are stated once in docs/runtime.md, "Q formats and rounding". The runtime's kernels run them
/// (codegen/runtime_filter.hpp); a checker (`admitgen check`) reads them back from a header.
///
/// Quantisation choices made here: a term's exponent is the largest that keeps its mantissas (a pair: the
/// sum |M_er| + |M_pi| + |M_g|) below 2^B with room for rounding, so ε = 1 − e^{−λT} keeps B significant
/// bits however slow the pole is; the output table's one exponent y_exp keeps Σ|M| below 2^B; out_shift is
/// the smallest with 2^out_shift ≥ ‖h‖₁ (1 + 2^−10) of the quantised filter.
#pragma once

#include "codegen/discrete_model.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace admitgen::codegen {

enum class Format { f32, q31, q15 };

/// "f32" | "q31" | "q15"; throws InputError otherwise.
Format parse_format(const std::string& text);
const char* format_name(Format format);

/// Mantissa fraction bits B of the coefficients of a fixed-point format: 31 (q31), 15 (q15), and 31 for q15 with
/// 32-bit coefficients (`wide`: Q1.15 data, the q31 tables; docs/runtime.md, "Q formats and rounding").
int coefficient_bits(Format format, bool wide = false);
/// Fraction bits D of a fixed-point format's data: 31 (q31), 15 (q15).
int data_bits(Format format);
/// The C type of the emitted tables: float, int32_t (q31, wide q15) or int16_t (q15).
const char* table_ctype(Format format, bool wide = false);

/// The f32 tables: exactly the float values emitted (the double model rounded to nearest).
struct FloatCoefficients {
  float h0 = 0.0f;
  std::vector<float> fir;
  std::vector<std::array<float, 2>> real;  ///< {ε, c}
  std::vector<std::array<float, 5>> pair;  ///< {e_r, p_i, g, 2 Re c, −2 Im c}
};

FloatCoefficients to_float(const DiscreteModel& model);

/// `model` with every coefficient replaced by the float the f32 tables hold: the filter the f32 kernel runs, in
/// exact arithmetic (as FixedCoefficients::dequantised is for q31/q15).
DiscreteModel as_emitted(const DiscreteModel& model, const FloatCoefficients& tables);

struct FixedCoefficients {
  Format format = Format::q31;
  int bits = 31;        ///< B: mantissa fraction bits (31 or 15)
  int out_shift = 0;    ///< output represents y · 2^−out_shift
  int y_exp = 0;        ///< output-table exponent
  int acc_shift = 0;    ///< R = B + 31 − D + out_shift − y_exp (D = data_bits: 31 + out_shift − y_exp for q31, q15)
  std::vector<std::int32_t> fir;
  struct Real {
    std::int32_t eps, shift, c;
  };
  struct Pair {
    std::int32_t e_r, p_i, g, shift, c_r, c_i;
  };
  std::vector<Real> real;
  std::vector<Pair> pair;
  double l1_norm = 0.0;  ///< ‖h‖₁ of the quantised filter (value units, before the output shift)

  /// q15 with 32-bit coefficients (bits = 31).
  bool wide() const { return format == Format::q15 && bits == 31; }
  /// What the kernel's output is, in value units, per unit of dequantised()'s response: the accumulator
  /// Σ m·s = y · 2^(B + 31 − y_exp) is shifted right by acc_shift into Q1.D with output scale 2^−out_shift, so
  /// 2^(B + 31 − D + out_shift − y_exp − acc_shift); 1 for a consistent header (docs/runtime.md).
  double output_gain() const;

  /// The double-precision model these integers represent exactly (for checkers and references).
  DiscreteModel dequantised(double fs_hz) const;
  /// Samples after which a state excited to full scale has reached exactly 0 with zero input
  /// (from |state_n| ≤ r^n |state_0| under magnitude truncation, plus the FIR length).
  int zero_decay_bound() const;
};

/// Quantises to q31 or q15 (throws InternalError for f32); `wide`: q15 with 32-bit coefficients.
FixedCoefficients quantise(const DiscreteModel& model, Format format, bool wide = false);

/// Replaces every pole of `model` (ε of a real term; e_r, p_i, g of a pair, and the λ, α, β they imply) by
/// the value `format` stores: rounded to float for f32, the mantissa and term exponent quantise() chooses
/// for q31/q15. The numerators are left alone. quantise() of the result stores the same poles again: the
/// values are exactly representable at the term's exponent, and only a mantissa sum within rounding of the
/// exponent's limit could make it choose a coarser one (the test of a narrow q15 pair checks the integers;
/// `admitgen check` reads what is written in any case).
void store_poles(DiscreteModel& model, Format format, bool wide = false);

}  // namespace admitgen::codegen

// SPDX-License-Identifier: MIT
/// @file
/// The coefficients actually emitted for one sample rate and format, and a bit-exact C++ model of the
/// fixed-point runtime kernels (runtime/src/admitgen_rt_process_q31.c, _q15.c): the source of golden
/// vectors and the object a checker (`admitgen check`) reads back from a header.
///
/// Fixed-point representation (ARM notation "1.31"/"1.15"; TI Q0.31/Q0.15). B = 31 (q31) or 15 (q15)
/// mantissa bits:
///  * input u: q31 as is; q15 promoted to Q31 by ×2^16 (exact). States ξ, η, x and the FIR history are
///    int32 Q31 for both formats ("wider state" for q15); every state is normalised so |state| ≤ max|u|.
///  * state-update coefficients, per term: mantissa M with its own exponent `shift` (delta form, so the
///    relative precision of ε = 1 − e^{−λT} is 2^−B whatever λT is — the 1 − e^{−λT} problem):
///      real: ε = M_eps · 2^−(B+shift);  pair: (e_r, p_i, g) = (M_er, M_pi, M_g) · 2^−(B+shift), with
///      |M_er| + |M_pi| + |M_g| < 2^B so the 64-bit sum of products cannot overflow.
///  * output table (FIR taps, c_q, 2 Re c_s, −2 Im c_s): one exponent y_exp, value = M · 2^(y_exp−B),
///    Σ|M| < 2^B, so |acc| < 2^(B+31) in the 64-bit accumulator.
///  * output: y_out = round(acc · 2^−acc_shift), saturated, where y_out represents y · 2^−out_shift and
///    2^out_shift ≥ ‖h‖₁ (L1 norm of the quantised filter): a full-scale worst-case-sign input cannot clip.
///  * rounding: state updates are rounded toward zero of the *new state value* (magnitude truncation,
///    which makes every state contract strictly: zero input decays to exactly 0, no limit cycle);
///    the output is rounded to nearest (half up); it is not fed back.
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

/// The f32 tables: exactly the float values emitted (the double model rounded to nearest).
struct FloatCoefficients {
  float h0 = 0.0f;
  std::vector<float> fir;
  std::vector<std::array<float, 2>> real;  ///< {ε, c}
  std::vector<std::array<float, 5>> pair;  ///< {e_r, p_i, g, 2 Re c, −2 Im c}
};

FloatCoefficients to_float(const DiscreteModel& model);

struct FixedCoefficients {
  Format format = Format::q31;
  int bits = 31;        ///< B: mantissa fraction bits (31 or 15)
  int out_shift = 0;    ///< output represents y · 2^−out_shift
  int y_exp = 0;        ///< output-table exponent
  int acc_shift = 0;    ///< R = 31 + out_shift − y_exp (the same for both formats)
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

  /// The double-precision model these integers represent exactly (for checkers and references).
  DiscreteModel dequantised(double fs_hz) const;
  /// Samples after which a state excited to full scale has reached exactly 0 with zero input
  /// (from |state_n| ≤ r^n |state_0| under magnitude truncation, plus the FIR length).
  int zero_decay_bound() const;
};

/// Quantises to q31 or q15 (throws InternalError for f32).
FixedCoefficients quantise(const DiscreteModel& model, Format format);

/// Q1.31 states of one node (x per real pole, ξ and η per pair, hist[k] = u^{n−k}, k < n_fir).
struct FixedState {
  std::vector<std::int32_t> x, xi, eta, hist;
};

/// Bit-exact model of admitgen_rt_process_q31 / _q15 for one node. Inputs are Q31 (q31) or Q15 values
/// (q15) held in int32; outputs likewise. Starts from zero state, or from *state when given (sized as
/// the coefficients), which then receives the final state.
std::vector<std::int32_t> run_fixed(const FixedCoefficients& coefficients, const std::vector<std::int32_t>& in,
                                    FixedState* state = nullptr);

}  // namespace admitgen::codegen

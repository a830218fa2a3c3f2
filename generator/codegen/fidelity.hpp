// SPDX-License-Identifier: MIT
/// @file
/// Fidelity of an emitted rate (docs/checks.md, "fidelity"): how far the filter the runtime executes is from
/// the continuous model G the header names, and how much the kernel's own rounding adds.
///
/// Deviation. The emitted coefficients, exactly as the kernel uses them (f32 values, or q31/q15 mantissas and
/// exponents: FixedCoefficients::dequantised, exact in double), define H(e^{jωT}); the deviation at f is
/// |H − G(j2πf)| / |G(j2πf)|. It is evaluated on kFidelityPoints log-spaced frequencies across the data band
/// (the band the refit matched; the data's own spacing is at least as coarse on the bundled files) and reported
/// separately from the data band's top to 0.45 fs (the part of the band above the data a wave solver still runs).
///
/// Rounding noise. For |u| ≤ 1 the kernel's rounding error at the output is bounded by
///   N = ½ LSB_out + LSB_state (Σ_q |c_q|/ε_q + Σ_s 2√2 |c_s|/(1 − |π_s|)),
/// each state update's rounding (< 1 LSB_state, magnitude truncation; docs/runtime.md, "Q formats and rounding")
/// propagated to the output through the term's own recursion (Σ_n |1 − ε|ⁿ = 1/ε; a pair's two states,
/// Σ_n |π|ⁿ = 1/(1 − |π|)). LSB_out = 2^(out_shift − 15) (q15), 2^(out_shift − 31) (q31); LSB_state = 2^−31.
/// f32: LSB_state = LSB_out = 2^−23 (one float rounding per update and per output sum, relative to full scale).
/// A full-scale tone at f then comes out with a signal-to-noise ratio of at least |H(f)| / N; below
/// kMinFullScaleSnrDb somewhere in band the output "can round to zero" there and the header fails.
#pragma once

#include "codegen/coefficients.hpp"
#include "codegen/discrete_model.hpp"
#include "model/multipole_surface.hpp"

namespace admitgen::codegen {

/// Default tolerance of the in-band deviation (`check --fidelity-tolerance`, `emit --fidelity-tolerance`).
inline constexpr double kDefaultFidelityTolerance = 5e-3;
/// The smallest full-scale signal-to-noise ratio in band a header may have (20 dB: a full-scale tone's output
/// at least 10× the kernel's rounding bound).
inline constexpr double kMinFullScaleSnrDb = 20.0;
/// Log-spaced frequencies over the data band at which the deviation is evaluated.
inline constexpr int kFidelityPoints = 1024;

struct Fidelity {
  double max_rel_deviation = 0.0;  ///< max over the data band of |H − G|/|G|
  double at_hz = 0.0;
  double max_rel_deviation_above = 0.0;  ///< the same from the data band's top to 0.45 fs (0 when empty)
  double above_at_hz = 0.0;
  double noise_floor = 0.0;        ///< N (value units, for |u| ≤ 1)
  double min_snr_db = 0.0;         ///< min over the data band of 20 log10(|H|/N)
  double snr_at_hz = 0.0;
};

/// The fidelity of `emitted` (the coefficients as stored: DiscreteModel of the header, and its fixed-point
/// tables for q31/q15, nullptr for f32) against `model` over the data band [f_lo, f_hi] Hz.
Fidelity fidelity(const MultipoleSurface& model, const DiscreteModel& emitted, const FixedCoefficients* fixed,
                  double f_lo, double f_hi);

}  // namespace admitgen::codegen

// SPDX-License-Identifier: MIT
/// @file
/// A 1D FDTD impedance tube terminated by the emitted C runtime, "measured" with two virtual
/// microphones and processed with the ISO 10534-2 two-microphone method (physics/two_microphone):
/// the simulation stage of `diagnose` (sim → runtime → wave solver → measurement).
///
/// Scheme (normalised: p, ũ = ρ0c0·u, so the wall law is ũ = G p with G the runtime's admittance).
/// Yee pressure-velocity leapfrog, p at nodes i = 0..M and times n, ũ at i+½ and n+½, Courant number
/// λ = c0T/h = 1, h = c0/fs:
///   ũ_{i+½}^{n+½} = ũ_{i+½}^{n−½} − (p_{i+1}^n − p_i^n),     p_i^{n+1} = p_i^n − (ũ_{i+½} − ũ_{i−½})^{n+½}.
/// At λ = 1 the 1D scheme is exactly a shift register for both travelling waves (p = f(n−i) + g(n+i)):
/// no numerical dispersion at any frequency below Nyquist, so a mic at node M−m sees e^{±jωmT}
/// exactly, and the grid spacing is no error source.
///  * wall (node M, half cell): velocity into the wall at n+½ is the trapezoidal mean of the runtime's
///    output, ū = (w^{n+1} + w^n)/2, w = runtime(p_M). With w^{n+1} = h0·p_M^{n+1} + s^n (instantaneous
///    gain + history, admitgen_rt_history_* / commit_*) the node is solved implicitly:
///        p_M^{n+1} (1 + h0) = p_M^n − s^n − w^n + 2 ũ_{M−½}^{n+½}.
///    Splitting p_M into the incident a and reflected b waves gives (z + 1)(b − a + w) = 0, so the
///    reflection is exactly R_d = (1 − Y_d)/(1 + Y_d) with Y_d(e^{jωT}) the runtime's own response: the
///    tube adds no error of its own, and whatever it measures beyond Y_d is the runtime's arithmetic
///    (float/fixed rounding of states and output, input quantisation, saturation) or the time window.
///  * source end (node 0): p_0^{n+1} = −ũ_{½}^{n+½} + q^{n+1}. For q = 0 this absorbs a left-going wave
///    exactly (g(n+1) = g(n+1)); q^{n+1} = f^{n+1} + f^n injects the right-going wave f. The excitation f
///    is a 1 s exponential sine sweep from f_min/2 to min(2 f_max, 0.49 fs), amplitude A = 0.3, 5 ms
///    fades: smooth spectrum without dips over the data band (H12 = P_near/P_far does not depend on it),
///    and its energy is spread over fs samples, so a fixed-point runtime's signal rounding (input 2^−B,
///    output 2^(out_shift−B)) is √fs smaller relative to the signal than with a single pulse.
///  * scaling: the runtime sees u = p_M with full scale 1. For a passive Y_d (|1 + Y_d| ≥ 1) a sinusoid
///    gives |p_M| = 2A/|1 + Y_d| ≤ 0.6; clipped inputs are counted (saturated_inputs).
///  * fixed-point runtimes (q31/q15) have no history/commit API: the history s^n is their output for
///    u = 0 on a byte copy of the instance's state (probe instance), h0 that of the dequantised tables;
///    p_M^{n+1} is then committed to the real instance, whose (rounded) output is w^{n+1}.
///  * microphones at pressure nodes M − m1 (far) and M − m2 (near): m = the nominal distance / h rounded
///    to the nearest node (≥ 1 cell of spacing); the processing uses these grid positions x1 = m1 h,
///    s = (m1 − m2) h, as a real tube's processing uses its real positions, so snapping is no error.
///  * spectra: the exact DTFT P(f) = Σ p^n e^{−j2πfn/fs} of each record at the data frequencies (not an
///    FFT: the data frequencies are not FFT bins, and interpolating between bins would add an error the
///    stage would be blamed for). H12 = P_near/P_far; R by ISO 10534-2 with k = 2πf/c0; y = (1 − R)/(1 + R).
///  * time window: automatic (window_s = 0) runs past the end of the sweep until the records and the wall
///    pressure have decayed, over a 1024-sample block, to 1e-14 of their peak or to 4 quanta of a
///    fixed-point runtime (at most kMaxSamples); a fixed window_s truncates the records, which is the
///    simulation setting that can be made too coarse.
/// The tube diameter plays no role: a 1D lossless tube carries plane waves only.
#pragma once

#include "codegen/coefficients.hpp"
#include "codegen/emission.hpp"

#include <Eigen/Core>

namespace admitgen::simulation {

struct TubeSimulationSettings {
  double c0 = 343.0;       ///< speed of sound [m/s] (sets h = c0/fs and k = 2πf/c0; cancels in kx)
  double spacing_m = 0.05;         ///< nominal microphone spacing s
  double mic1_distance_m = 0.1;    ///< nominal sample face to the far microphone x1
  double window_s = 0.0;   ///< record length; 0 = automatic (until the response has decayed)
  static constexpr long kMaxSamples = 1L << 20;
};

struct TubeSimulationResult {
  Eigen::ArrayXcd y;   ///< the admittance the virtual measurement reports at the data frequencies
  Eigen::ArrayXcd r;   ///< its reflection factor
  int m1 = 0, m2 = 0;  ///< grid nodes of the far and near microphone, counted from the wall
  double x1_m = 0.0, spacing_m = 0.0;  ///< the positions the processing used (grid nodes)
  long samples = 0;    ///< time steps run and recorded
  bool decayed = false;          ///< the automatic window ended by decay (not by kMaxSamples / window_s)
  double peak_wall_pressure = 0.0;  ///< max |p_M| (full scale 1)
  long saturated_inputs = 0;     ///< fixed point: wall pressures clipped to full scale
};

/// Runs the tube with the runtime of `format` executing `rate`'s emitted tables (rate.f32 for f32,
/// rate.fixed for q31/q15) and measures y at f_hz (ascending, below 0.5 fs). Throws InputError if the
/// runtime refuses the tables or the geometry leaves no room for two distinct microphones.
TubeSimulationResult simulate_impedance_tube(const codegen::EmittedRate& rate, codegen::Format format,
                                             const Eigen::ArrayXd& f_hz, const TubeSimulationSettings& settings);

}  // namespace admitgen::simulation

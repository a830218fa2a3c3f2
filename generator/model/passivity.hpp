// SPDX-License-Identifier: MIT
/// @file
/// Exact passivity (positive-realness) test of a stable rational admittance, docs/physics.md §2.3:
/// Re G(jω) ≥ 0 for every ω ≥ 0, decided by the imaginary-axis eigenvalues of the Hamiltonian matrix
/// (Boyd, Balakrishnan & Kabamba 1989; Grivet-Talocia 2004, IEEE TCAS-I 51(9)), not by sampling:
///
///   M = [ A − B R⁻¹ C      −B R⁻¹ Bᵀ          ]      R = D + Dᵀ = 2D,
///       [ Cᵀ R⁻¹ C        −Aᵀ + Cᵀ R⁻¹ Bᵀ     ]      jω₀ ∈ eig(M)  ⇔  Re G(jω₀) = 0.
///
/// The crossings split [0, ∞) into intervals on which Re G has one sign. Re G is evaluated at every crossing
/// candidate, the midpoint of each gap, a dense log net, and windows around every pair's resonance and every
/// eigenvalue near the axis (two crossings closer than rounding resolves leave the axis as a pair ±δ + jω_m);
/// every local minimum of those samples is refined, and any value below 0 is a negative band whose edges are
/// polished by bisection (docs/passivity.md, "What the certificate guarantees"). When D ≈ 0 the reciprocal
/// realisation of G(1/s) (A⁻¹, A⁻¹B, −CA⁻¹, G(0)) supplies the eigenvalues (PR is invariant under s → 1/s);
/// when both G(∞) and G(0) vanish, G + ε does (ε = 1e-6 of the model's scale); the sign is always that of
/// Re G itself.
///
/// Discrete filters (what is emitted) are tested by the same decision through the bilinear map
/// z = (1 + s)/(1 − s) (checks/passivity.hpp), crossings at θ = 2 atan ω.
#pragma once

#include "model/order.hpp"
#include "model/state_space.hpp"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace admitgen {

/// A frequency band where Re G < 0. Units: those of the function that returned it.
struct NegativeBand {
  double lo = 0.0, hi = 0.0;  ///< hi = +inf: the band extends to infinite frequency (continuous) / Nyquist
  double min_re = 0.0;        ///< minimum of Re G in the band
  double at = 0.0;            ///< where it is reached
};

struct PassivityResult {
  bool passive = true;
  std::string method;              ///< which realisation decided it (see the file comment)
  std::vector<double> crossings;   ///< frequencies where Re G = 0, ascending (polished)
  std::vector<NegativeBand> bands; ///< ascending
  double min_re = 0.0;             ///< minimum of Re G found (bands, crossings, a dense log scan)
  double min_at = 0.0;
};

/// Re G(jω) at a native frequency ω ≥ 0 (must be accurate: it decides the sign on each interval).
using RealPartFn = std::function<double(double omega)>;

/// A frequency window where Re G can vary quickly (a pair's resonance: centre β, half width α), sampled densely
/// by the certificate (31 points spaced as resonance_points). Native frequency units.
struct FeatureWindow {
  double centre = 0.0, half = 0.0;
};

/// Eigenvalues λ (Im λ ≥ 0) of the Hamiltonian of ss (R = 2D, D ≠ 0), native frequency units.
std::vector<std::complex<double>> hamiltonian_eigenvalues(const StateSpace& ss);

/// The test of a stable realisation (native frequency ω, rad/s for a continuous G); docs/passivity.md, "What
/// the certificate guarantees". `scan_lo`..`scan_hi` bound the net of direct evaluations (200 points per decade,
/// the reported minimum's scan; `scan_minimum` false: 32, for certifiers in a loop whose result is certified
/// again). `features`: windows sampled densely besides those of the Hamiltonian's eigenvalues. Passive only if
/// no evaluated Re G is below 0 (no tolerance).
PassivityResult hamiltonian_passivity(const StateSpace& ss, const RealPartFn& re, double scan_lo, double scan_hi,
                                      bool scan_minimum = true, const std::vector<FeatureWindow>& features = {});

/// The resonance windows of a multipole's pairs (centre |β_s|, half width α_s; rad/s).
std::vector<FeatureWindow> resonance_windows(const Order& order, const double* theta);

/// Continuous multipole G (θ packed as model/order.hpp); frequencies in Hz. Requires λ, α > 0.
PassivityResult continuous_passivity(const Order& order, const double* theta);

/// Fast exact decision for the fitter: G∞ < 0 or Re G(0) < 0 reject at once, the term-wise sufficient
/// conditions (G∞ ≥ 0, A_q ≥ 0, |C_s| β_s ≤ B_s α_s; docs/physics.md §2.2) accept at once, the Hamiltonian
/// test decides the rest. False for a non-causal model (λ or α ≤ 0).
bool is_passive(const Order& order, const double* theta);

/// Constraint points across one resonance of half width `half` at `centre` (any unit): centre + half·tan φ,
/// φ uniform in (−π/2, π/2), 31 points. They resolve the Lorentzian Re G of a narrow pair (α ≪ β) that a
/// log or linear grid steps over (the passive refits of passivity/passive_residues.hpp and of
/// codegen/discrete_model.hpp seed their constraint grids with them). Callers drop points outside their range.
std::vector<double> resonance_points(double centre, double half);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
/// @file
/// Exact passivity (positive-realness) test of a stable rational admittance, docs/physics.md §2.3:
/// Re G(jω) ≥ 0 for every ω ≥ 0, decided by the imaginary-axis eigenvalues of the Hamiltonian matrix
/// (Boyd, Balakrishnan & Kabamba 1989; Grivet-Talocia 2004, IEEE TCAS-I 51(9)), not by sampling:
///
///   M = [ A − B R⁻¹ C      −B R⁻¹ Bᵀ          ]      R = D + Dᵀ = 2D,
///       [ Cᵀ R⁻¹ C        −Aᵀ + Cᵀ R⁻¹ Bᵀ     ]      jω₀ ∈ eig(M)  ⇔  Re G(jω₀) = 0.
///
/// The crossings split [0, ∞) into intervals on which Re G has one sign; one evaluation per interval
/// decides it, and every negative interval's edges are polished by bisection on Re G. When D ≈ 0 the
/// reciprocal realisation of G(1/s) (A⁻¹, A⁻¹B, −CA⁻¹, G(0)) is tested instead (PR is invariant under
/// s → 1/s; crossings map ω ↔ 1/ω); when both G(∞) and G(0) vanish, G + ε is tested (ε = 1e-6 of the
/// model's scale; the result then proves Re G ≥ −ε and says so).
///
/// Discrete filters (what is emitted) are tested by the same decision through the bilinear map
/// z = (1 + s)/(1 − s) (checks/passivity.hpp), crossings at θ = 2 atan ω.
#pragma once

#include "model/order.hpp"
#include "model/state_space.hpp"

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

/// Imaginary-axis eigenvalues ω ≥ 0 of the Hamiltonian of ss (R = 2D, D ≠ 0), ascending; eigenvalues with
/// |Re λ| ≤ 1e-5 |λ| count (a tolerance that may add candidates, which the sign evaluation then discards,
/// but does not lose crossings to rounding).
std::vector<double> hamiltonian_crossings(const StateSpace& ss);

/// The exact test of a stable realisation (native frequency ω, rad/s for a continuous G).
/// `scan_lo`..`scan_hi` bound the dense scan that only feeds the reported minimum; `scan_minimum` false
/// skips that scan (min_re/min_at then come from D and the negative bands only; the decision and the
/// bands are the same; for certifiers in a loop).
PassivityResult hamiltonian_passivity(const StateSpace& ss, const RealPartFn& re, double scan_lo, double scan_hi,
                                      bool scan_minimum = true);

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

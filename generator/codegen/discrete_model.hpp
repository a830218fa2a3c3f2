// SPDX-License-Identifier: MIT
/// @file
/// Continuous multipole admittance → discrete filter at one sample rate (docs/physics.md §1.2-1.3).
///
/// Method "matched-exponential, refitted numerators":
///  * every pole keeps its exact discrete image z = e^{-aT} (the PLRC/FOH pole; L-stable, so a stiff
///    pole never leaves the sign-alternating tail a bilinear pole with aT > 2 would);
///  * the residues, the direct term and a short FIR path d_0..d_{L-1} are then fitted by weighted
///    linear least squares so that H(e^{jωT}) matches the continuous G(jω) at the fit's data frequencies
///    (relative error, weight 1/|G|²) — "matched pole, fitted numerator" (docs/physics.md §1.3 item 3b).
///    PLRC alone leaves a second-order error ~ x/12·K T, x = (a + jω)T (Bernoulli expansion of
///    1/(1 − e^{−x})); the FIR taps absorb that polynomial in jωT, which residues alone cannot;
///  * poles decaying fast compared with the rate (a/2π > fold_factor · fs; e.g. above Nyquist, so that
///    z = e^{−aT} < e^{−π} = 0.043) are folded into the FIR path: their state all but vanishes within one
///    sample, while their in-band response A/(λ + jω) is a smooth function of jωT the FIR taps reproduce
///    (measured on the reference Q1S1 fit at 16 kHz: 0.8 % max error folded vs 25 % kept).
///
/// Realisation (the form the runtime executes; states are normalised so |state| ≤ max|u|):
///   real term  x' = x + ε (u − x),                 ε = 1 − e^{−λT},          y += c x
///   pair       ψ' = π ψ + g u,  π = e^{−(α+jβ)T},  g = 1 − |π|,             y += 2 Re(c ψ)
///              i.e. ξ' = ξ + e_r ξ − p_i η + g u,  η' = η + e_r η + p_i ξ,   e_r = Re π − 1, p_i = Im π
///   FIR        y += Σ_k d_k u^{n−k}
/// so that y^n = h0 u^n + s^{n−1} with h0 = d_0 + Σ c ε + Σ 2 Re(c) g (instantaneous gain + history).
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>

#include <complex>
#include <utility>
#include <functional>
#include <string>
#include <vector>

namespace admitgen::codegen {

/// One real pole in delta (leaky-integrator) form.
struct RealTerm {
  double lambda = 0.0;  ///< continuous rate [1/s]
  double eps = 0.0;     ///< 1 − e^{−λT}, computed with expm1 (exact even for λT ≪ 1)
  double c = 0.0;       ///< output coefficient (= the term's DC gain A/λ for PLRC)
};

/// One complex pair in coupled (rotation × decay) form.
struct PairTerm {
  double alpha = 0.0, beta = 0.0;  ///< continuous pole −α − jβ [1/s]
  double e_r = 0.0;                ///< Re π − 1 = e^{−αT} cos βT − 1 (computed without cancellation)
  double p_i = 0.0;                ///< Im π = −e^{−αT} sin βT
  double g = 0.0;                  ///< input gain 1 − e^{−αT}
  std::complex<double> c;          ///< output coefficient: y += 2 Re(c ψ) = 2 c_r ξ − 2 c_i η
};

/// |z| < 1 of a term's pole, decided in double: z = 1 − ε for a real term, |1 + e_r + j p_i|² < 1 for a
/// pair (exact for f32 coefficients; the discrete_stability check decides q31/q15 in integers).
bool inside_unit_circle(const RealTerm& term);
bool inside_unit_circle(const PairTerm& term);

/// Upper bounds of ‖ξ‖₁ and ‖η‖₁ for ψ_n = πⁿ g (the pair's state impulse response, docs/physics.md §3.3: the
/// largest |state| a full-scale input of any sign pattern reaches): the explicit sum over n < N plus the tail
/// bound g rᴺ/(1 − r), N where that tail is below 1e-13 (at most 2^22 samples). +∞ when |π| ≥ 1.
std::pair<double, double> state_l1(const PairTerm& term);

struct DiscreteModel {
  double fs_hz = 0.0;
  std::vector<double> fir;  ///< d_0 … d_{L−1}
  std::vector<RealTerm> real;
  std::vector<PairTerm> pair;
  std::vector<std::string> folded;  ///< terms folded into the FIR path, e.g. "lambda_2 = 9.1e6 1/s"
  double refit_max_rel_error = 0.0;  ///< max |H − G|/|G| at the data frequencies after the refit
  double plrc_max_rel_error = 0.0;   ///< the same for plain PLRC coefficients (what the refit removed)
  bool passive_certified = false;    ///< certified by DiscretiseOptions::passivity_violations (when given)
  int passive_rounds = 0;            ///< constraint-generation rounds the certification took (0: none needed)

  /// Instantaneous gain h0 of y^n = h0 u^n + s^{n−1}.
  double h0() const;
  /// H(e^{j2πf/fs}).
  std::complex<double> response(double f_hz) const;
  /// Output for input u in double precision: the exact-arithmetic reference every format is compared with
  /// (the runtime has no double kernel). The shipped float and fixed-point arithmetic is never re-implemented
  /// here: codegen/runtime_filter.hpp runs the runtime's own kernels.
  std::vector<double> filter(const std::vector<double>& u) const;
  std::vector<double> impulse_response(int n) const;
  /// Every pole strictly inside the unit circle (inside_unit_circle).
  bool stable() const;
  /// Σ|h[n]| over n < until the tail is below 1e-12 of the peak (bounds |y| for |u| ≤ 1); +∞ when the
  /// filter is not stable.
  double l1_norm() const;
  /// Samples until every pole's envelope has decayed by `decades` decades.
  int tail_samples(double decades) const;
};

struct DiscretiseOptions {
  int fir_taps = 0;            ///< 0: smallest L in [1, kMaxFirTaps] reaching `target_rel_error`, else the best
  /// Fold a pole when its rate / 2π exceeds fold_factor · fs; 0 (auto): the best refit of fold_factor
  /// 0.25, 0.5 and 4 (reference Q1S1 fit, pole at 9.3 kHz: folding wins at 16 and 24 kHz, keeping at 48 kHz).
  double fold_factor = 0.0;
  double target_rel_error = 1e-5;
  /// Passivity certifier (emit passes the discrete Hamiltonian test, checks/passivity.hpp): the
  /// frequencies (Hz) of a candidate where Re H(e^{j2πf/fs}) < 0, empty when Re H ≥ 0 up to Nyquist.
  /// A candidate is certified when Re H ≥ passive_margin · max|G| up to Nyquist (the certifier is given
  /// H minus that margin). When set, every refit whose least-squares solution is not certified is solved again under
  /// Re H(e^{jθ_j}) ≥ passive_margin · max|G| on a grid of θ_j ∈ [0, π] plus every violation found
  /// (constraint generation, docs/passivity.md), and a certified candidate beats any that is not.
  std::function<std::vector<double>(const DiscreteModel&)> passivity_violations;
  /// Margin of the constraints above, relative to max|G| over the data (it absorbs coefficient rounding).
  double passive_margin = 1e-9;
  /// When set, replaces every kept pole by its value as the emitted format stores it (codegen/coefficients.hpp
  /// store_poles) before the numerators are refitted, so that the refit and its passivity certificate hold for
  /// the poles the header carries, not only for the exact images e^{−aT} (docs/passivity.md, "Refit to the
  /// stored poles"). A narrow pair's rounded pole moves its resonance by a fraction of its width.
  std::function<void(DiscreteModel&)> store_poles;
  static constexpr int kMaxFirTaps = 8;
};

/// Discretises G (order, θ packed as model/order.hpp) at fs_hz, refitting at data_f_hz (Hz).
/// Throws InputError if a data frequency is not below 0.45 fs (it cannot be represented).
DiscreteModel discretise(const Order& order, const Eigen::VectorXd& theta, double fs_hz,
                         const std::vector<double>& data_f_hz, const DiscretiseOptions& options = {});

}  // namespace admitgen::codegen

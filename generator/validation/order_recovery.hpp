// SPDX-License-Identifier: MIT
/// @file
/// Order recovery (docs/validation.md, "Order recovery"): data simulated from a known order (validation/
/// calibration.hpp simulate: plausible draws from Table 1 clipped to the band, band_priors(grid, table1), fixed
/// relative noise), fitted over the whole grid by run_fit as `fit` does with the priors under test (base_priors),
/// the selected order against the truth.
///
/// Identifiability of the truth. Its competitors are the orders of the fitted grid that cannot represent
/// it (Q' < Q or S' < S) with at most as many terms (Q' + S' ≤ Q + S): the orders one term smaller, and
/// those with a real pole in place of a pair or a pair in place of a real pole (a pair with β → 0 and a
/// real pole, or two real poles and a heavily damped pair, can make nearly the same admittance over a
/// band). For each, its maximum-likelihood model Ĝ from the same fit; the measure is
///   D = min over the competitors of ‖G_true − Ĝ‖ / σ_c,   ‖x‖² = Σ_i |x_i|² over the N points,
/// σ_c the complex noise std. D² is the gain in the best ln L that the truth's structure brings over the
/// closest competitor at known σ (per real component variance σ_c²/2), i.e. how strongly the data ask for
/// it. The truth is identifiable when D ≥ kIdentifiableDistance = 10 (a gain of 100 nats, 2.5× the largest
/// Occam penalty of one term: a pair has 4 parameters, each known to ≳ 1e-4 of its prior width,
/// ln 1e4 · 4 ≈ 37 nats). Below it a competitor may legitimately win. The same D over the one-term-smaller
/// orders alone (whether the last term is needed at all, not which kind it is) is reported as
/// distance_smaller, and the RMS form D/√N too (docs/validation.md, "Order recovery").
#pragma once

#include "selection/fit.hpp"
#include "validation/calibration.hpp"

#include <functional>
#include <string>
#include <vector>

namespace admitgen::validation {

constexpr double kIdentifiableDistance = 10.0;

/// How the true models are drawn. `prior`: the calibration's plausible prior (validation/calibration.hpp),
/// where most truths of three or more terms hide a term behind the others (unidentifiable). `distinct`: that
/// prior further restricted to models whose terms are told apart by the band (distinct_terms below), the
/// design that measures the identifiable rate on many sets. D decides identifiability in both.
enum class RecoveryDesign { prior, distinct };

/// The `distinct` restriction (docs/validation.md, "Order recovery"): the natural frequencies (λ_q,
/// |α_s + jβ_s|) at least a factor kDistinctRatio apart from each other, every pair resonant (quality factor
/// |θ_s|/(2α_s) ≥ kMinPairQuality, damping ratio ≤ ½, so that no real pole or pair of real poles mimics it),
/// and every term's share ‖term‖/‖G‖ over the grid ≥ kMinTermShare (‖·‖ the 2-norm over the points). At the
/// largest noise of the map (3 % of rms|G|, 150 points) a term of that share stands kMinTermShare·√N/0.03 ≈
/// 41 σ above the noise. Invariant under the label symmetries. Rejection from the tube grid's plausible prior
/// needs ~35 draws per Q0S1 truth, ~5·10⁴ per Q0S3 or Q2S2, ~2.6·10⁵ per Q1S3 and ~5·10⁶ per Q2S3 (one of
/// three seeds within simulate's cap of 10⁷), so the distinct map leaves Q2S3 out.
constexpr double kDistinctRatio = 1.5;
constexpr double kMinPairQuality = 1.0;
constexpr double kMinTermShare = 0.1;
bool distinct_terms(const Order& order, const double* theta, const Eigen::ArrayXd& omega);

struct RecoverySettings {
  std::vector<Order> truths = order_range(0, 2, 1, 3);  ///< Q0-2 × S1-3
  std::vector<double> noise{0.003, 0.01, 0.03};
  int per_cell = 3;          ///< data sets per (truth, noise)
  Grid grid = tube_grid();
  int qmax = 3, smax = 3;    ///< the fitted grid
  int live = 100;
  int runs = 1;              ///< independent runs per order (FitSettings::runs)
  std::vector<SamplerKind> samplers{SamplerKind::full};
  /// The evidence rule unless set: order recovery asks whether the evidence finds the true order, which the fit's
  /// default rule `target` does not try to (it ships the cheapest order meeting the accuracy target, often fewer
  /// terms than the truth on low-noise data: docs/method.md, "Accuracy target").
  SelectionRule rule = SelectionRule::simplest(10.0);
  RecoveryDesign design = RecoveryDesign::prior;
  std::uint64_t seed = 1;
  int threads = 0;
  PriorRanges base_priors = default_base_priors();  ///< made the grid's prior by band_priors, for the fits
  /// Data set indices to run (empty: all). Index i = (truth t, noise k, replicate r) with
  /// i = (t·|noise| + k)·per_cell + r; its seed depends on i and the seed only, so one set can be re-run alone.
  std::vector<int> cases;

  /// Orders Q ∈ [q0, q1] × S ∈ [s0, s1], Q-major.
  static std::vector<Order> order_range(int q0, int q1, int s0, int s1);
};

/// One order's fit of a recovery data set: what decides the selection, so that a miss can be attributed
/// (an over-complete order's evidence too high, or the truth's too low).
struct OrderEvidence {
  Order order{0, 0};
  double log_z = 0.0, log_z_error = 0.0;
  double max_log_l = 0.0;  ///< best ln L the run found
  std::string sampler;     ///< ModelResult::sampler ("poles_box_mass_sampled", ...)
  int live = 0;            ///< live points of the run kept (more after a missed-mode re-run)
};

struct RecoveryCase {
  int index = 0;
  Order truth{0, 0};
  double noise = 0.0;
  std::string sampler;
  Order selected{0, 0};
  double distance = 0.0;     ///< D over the competitors (see the file comment)
  double distance_smaller = 0.0;  ///< D over the one-term-smaller orders alone (≥ distance)
  double rms_sigma = 0.0;    ///< D/√N
  Order nearest{0, 0};       ///< the competitor that attains D
  bool identifiable = false;
  int extra_terms = 0;       ///< (Q + S) selected − (Q + S) true
  int fallbacks = 0;         ///< orders that ran the full sampler when the pole sampler was asked for (selection/fit.hpp)
  std::vector<OrderEvidence> evidence;  ///< every order of the fitted grid, grid order
  double log_l_truth = 0.0;  ///< ln L of the true θ (the fit's likelihood, data_count two per point)
  Measurement data;          ///< the simulated data set
};

/// Whether `order` competes with `truth` (see the file comment): it cannot represent the truth and has no
/// more terms.
bool is_competitor(const Order& order, const Order& truth);

/// Every (truth, noise, replicate) data set fitted with every sampler; data set i uses the same simulation
/// for every sampler. In parallel over `threads` (each fit single-threaded); independent of the thread count.
std::vector<RecoveryCase> run_recovery(const RecoverySettings& settings,
                                       const std::function<void(const RecoveryCase&)>& done = {});

}  // namespace admitgen::validation

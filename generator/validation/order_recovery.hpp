// SPDX-License-Identifier: MIT
/// @file
/// Order recovery (docs/validation.md, "Order recovery"): data simulated from a known order (validation/
/// calibration.hpp simulate: plausible draws from band_priors, fixed relative noise), fitted over the whole
/// grid by run_fit as `fit` does (with the same priors), the selected order against the truth.
///
/// Identifiability of the truth's last term. For each order one term smaller that the truth contains,
/// (Q − 1, S) and (Q, S − 1), take its maximum-likelihood model Ĝ from the same fit; the measure is
///   D = min over those orders of ‖G_true − Ĝ‖ / σ_c,   ‖x‖² = Σ_i |x_i|² over the N points,
/// σ_c the complex noise std. D² is the gain in the best ln L that the truth's extra term brings at known σ
/// (per real component variance σ_c²/2), i.e. how strongly the data ask for it. The truth is identifiable
/// when D ≥ kIdentifiableDistance = 10 (a gain of 100 nats, 2.5× the largest Occam penalty of one term: a pair
/// has 4 parameters, each known to ≳ 1e-4 of its prior width, ln 1e4 · 4 ≈ 37 nats). Below it a smaller
/// order may legitimately win. The RMS form D/√N is reported too.
#pragma once

#include "selection/fit.hpp"
#include "validation/calibration.hpp"

#include <functional>
#include <string>
#include <vector>

namespace admitgen::validation {

constexpr double kIdentifiableDistance = 10.0;

struct RecoverySettings {
  std::vector<Order> truths = order_range(0, 2, 1, 3);  ///< Q0-2 × S1-3
  std::vector<double> noise{0.003, 0.01, 0.03};
  int per_cell = 3;          ///< data sets per (truth, noise)
  Grid grid = tube_grid();
  int qmax = 3, smax = 3;    ///< the fitted grid
  int live = 100;
  std::vector<SamplerKind> samplers{SamplerKind::full};
  std::uint64_t seed = 1;
  int threads = 0;
  PriorRanges base_priors = PriorRanges::table1();  ///< clipped to the band by band_priors, for truths and fits

  /// Orders Q ∈ [q0, q1] × S ∈ [s0, s1], Q-major.
  static std::vector<Order> order_range(int q0, int q1, int s0, int s1);
};

struct RecoveryCase {
  int index = 0;
  Order truth{0, 0};
  double noise = 0.0;
  std::string sampler;
  Order selected{0, 0};
  double distance = 0.0;     ///< D (see the file comment)
  double rms_sigma = 0.0;    ///< D/√N
  Order nearest{0, 0};       ///< the one-term-smaller order that attains D
  bool identifiable = false;
  int extra_terms = 0;       ///< (Q + S) selected − (Q + S) true
  int fallbacks = 0;         ///< orders the pole sampler re-ran with the box mass sampled (selection/fit.hpp)
};

/// Every (truth, noise, replicate) data set fitted with every sampler; data set i uses the same simulation
/// for every sampler. In parallel over `threads` (each fit single-threaded); independent of the thread count.
std::vector<RecoveryCase> run_recovery(const RecoverySettings& settings,
                                       const std::function<void(const RecoveryCase&)>& done = {});

}  // namespace admitgen::validation

// SPDX-License-Identifier: MIT
/// @file
/// Nested sampling (Skilling 2006) with a constrained step by slice sampling along random directions
/// whitened by the live points' covariance (as PolyChord, Handley et al. 2015, and dynesty's
/// "rslice", Speagle 2020). The sampler knows nothing about acoustics: it takes a model
/// (inference/model.hpp), a prior transform from the unit cube and a log-likelihood over flat vectors.
///
/// Bookkeeping (Skilling 2006, §3-4): after i deaths the expected prior volume is X_i = e^{−i/n}; dead
/// point i carries weight w_i = L_i (X_{i−1} − X_i); Z = Σ w_i plus the live points' share X_end·mean(L)
/// at the end; the information H = Σ (w_i/Z) ln(L_i/Z); the error of ln Z is √(H/n).
#pragma once

#include "inference/model.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace admitgen {

/// The stop dynesty uses by default when the live points close the run (Speagle 2020): 0.01 + 0.001 (n − 1).
/// The live points then hold at most e^{dlogz} − 1 of the evidence found so far, which the close adds with
/// their mean likelihood; a lower stop adds iterations of live points that change ln Z by less than its error.
double automatic_dlogz(int live);

struct NestedSettings {
  int live = 500;                      ///< number of live points n
  /// Stop when ln(Z + X·L_max) − ln Z < dlogz; unset: automatic_dlogz(live) (stop_dlogz()).
  std::optional<double> dlogz;
  long max_iterations = 1'000'000;     ///< safety cap on deaths
  int slices = 0;                      ///< 1-D slices per replacement; 0 = automatic (3 + dim)
  std::uint64_t seed = 1;
  int covariance_interval = 0;         ///< iterations between covariance updates; 0 = live/10
  /// Constrained step by uniform draws in the live points' bounding ellipsoid (inference/ellipsoid_union.hpp),
  /// each kept when above the contour, while the live points form one cluster and the draws cost fewer calls
  /// than a slice chain; a replacement that finds none within a slice chain's calls moves by slices instead
  /// (the rule is stated at Replacement in nested_sampler.cpp). false: slices only.
  bool ellipsoid_draws = false;
  /// Volume of each bounding ellipsoid over the tightest one of its shape that holds its cluster.
  double ellipsoid_enlarge = 2.0;

  /// The stop in force: dlogz, or automatic_dlogz(live) when unset.
  double stop_dlogz() const { return dlogz ? *dlogz : automatic_dlogz(live); }
  /// The slices per replacement in force in `dim` dimensions: slices, or 3 + dim (as dynesty's rslice,
  /// Speagle 2020) when 0.
  int slices_per_replacement(int dim) const { return slices > 0 ? slices : 3 + dim; }
};

/// Status of a run after a death: for progress display and early stops.
struct NestedStatus {
  long iteration;
  double log_z;
  double remaining;  ///< current ln(Z + X·L_max) − ln Z
  long calls;
  double log_x = 0.0;             ///< ln X, the prior volume left inside the contour
  double log_l_contour = 0.0;     ///< ln L* of the point that just died
  double log_l_max_live = 0.0;    ///< the best ln L among the live points
};

struct NestedRun {
  int dim = 0;
  std::vector<double> samples;         ///< row-major, one row of dim θ values per point (dead, then final live)
  std::vector<double> log_likelihood;  ///< per point
  std::vector<double> log_weight;      ///< ln(L_i ΔX_i), unnormalised; posterior p_i = exp(log_weight_i − log_z)
  /// The likelihood the run sampled, per point, where log_likelihood holds another (the pole sampler's
  /// marginal ln L(ψ), inference/poles_sampler.hpp); empty when log_likelihood is it.
  std::vector<double> sampled_log_likelihood;
  double log_z = 0.0;
  double log_z_error = 0.0;            ///< √(H/n)
  double information = 0.0;            ///< H in nats
  double max_log_likelihood = 0.0;
  long calls = 0;                      ///< likelihood evaluations (initial live points included)
  long iterations = 0;                 ///< deaths
  /// "dlogz", "max_iterations" or "early_stop"; runs of the same shape made otherwise say "analytic"
  /// (no parameter to sample) or "quadrature" (inference/quadrature_evidence.hpp).
  std::string stopped_by;
  /// ln of the prior fraction with finite likelihood, estimated from the initial draws (0 when ln L is
  /// never −∞). ln Z is the evidence under the prior renormalised to that support; ln Z + this is
  /// ln ∫ L π over the original prior.
  double log_support_fraction = 0.0;

  std::size_t size() const { return log_likelihood.size(); }
  const double* point(std::size_t i) const { return samples.data() + i * static_cast<std::size_t>(dim); }
};

using NestedProgressFn = std::function<void(const NestedStatus&)>;
/// Optional early stop: asked after every death; returning true ends the run there (stopped_by
/// "early_stop"), the live points then closing it as at the dlogz stop.
using NestedStopFn = std::function<bool(const NestedStatus&)>;

/// Runs nested sampling on `model` to completion. Deterministic for a given seed (single-threaded).
NestedRun run_nested_sampling(const Model& model, const NestedSettings& settings,
                              const NestedProgressFn& progress = {}, const NestedStopFn& stop = {});

}  // namespace admitgen

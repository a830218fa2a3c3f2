// SPDX-License-Identifier: MIT
/// @file
/// The passive estimate of a fitted order (docs/passivity.md, "Passive estimate"). For each of the
/// highest-likelihood posterior samples (kCandidates of them), keep its poles and take the residues that
/// fit the data best (the likelihood's own unweighted least squares) among those that make Re G(jω) ≥ 0
/// at every ω (passivity/passive_residues.hpp); a sample that is already passive is kept as it is. When the
/// best sample is not passive, the poles are then searched too (passivity/pole_refit.hpp) from the
/// kStarts best of these candidates, and each result is certified again. The estimate is the certified
/// candidate with the highest likelihood.
/// It is what `emit` uses by default: a filter that is passive by construction, at a cost in fit that is
/// reported (docs/passivity.md, "What passivity costs").
#pragma once

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "inference/priors.hpp"
#include "model/order.hpp"
#include "numerics/passive_bound.hpp"

#include <Eigen/Core>

#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace admitgen::passivity {

/// The passive bound (numerics/passive_bound.hpp; docs/passivity.md, "The passive bound") of a measurement with
/// the likelihood's unit weights, computed once, when first asked for (the orders of a fit ask from several
/// threads; the value does not depend on which one computes it). Most fits never ask: only an estimate that costs more than 1.25x the best sample's residual is explained with it.
class LazyPassiveBound {
 public:
  explicit LazyPassiveBound(const Measurement& data) : data_(data) {}
  const numerics::PassiveBound& get() const;

 private:
  const Measurement& data_;
  mutable std::once_flag computed_;
  mutable std::optional<numerics::PassiveBound> bound_;
};

struct PassiveEstimate {
  /// Candidates tried: poles of the best samples differ little, but where the best sample's residues
  /// violate passivity strongly a slightly worse sample can be much better once made passive.
  static constexpr int kCandidates = 16;
  /// Starts of the pole search: the best candidates after the residue refit (docs/passivity.md, "Searching
  /// the poles": the measured gain of more starts is below 1 % of the residual).
  static constexpr int kStarts = 4;
  /// Levenberg–Marquardt steps per start (converged runs of the bundled files take 10-40).
  static constexpr int kMaxSteps = 60;
  /// A passive estimate whose residual exceeds the best sample's by more than this factor is reported with
  /// its cost (warning and fit.json's passivity_cost; docs/passivity.md, "What passivity costs").
  static constexpr double kCostRatio = 1.25;
  static constexpr const char* kPolesFrom =
      "the best (after the passive residue refit) of the 16 highest-likelihood posterior samples";
  static constexpr const char* kPolesSearched =
      "searched: least squares in poles and residues under Re G >= 0, from the 4 best of the 16 highest-likelihood "
      "posterior samples after the passive residue refit";
  int candidate_rank = 0;                    ///< 0 = the highest-likelihood sample (the start, when searched)
  Eigen::VectorXd theta;                     ///< packed as model/order.hpp
  double log_likelihood = 0.0;               ///< ln L of theta (inference/likelihood.hpp)
  double relative_rms_residual = 0.0;        ///< √(Σ|D − G|² / Σ|D|²) of theta
  double best_sample_relative_rms_residual = 0.0;  ///< the same for the highest-likelihood sample
  double best_sample_log_likelihood = 0.0;
  bool certified = false;                    ///< Hamiltonian test: Re G ≥ 0 for every ω
  double min_re = 0.0;                       ///< minimum of Re G found by the certificate's scan
  int rounds = 0;                            ///< constraint-generation rounds
  bool changed = false;                      ///< false when the best sample was already passive and kept
  bool poles_searched = false;               ///< the poles were moved by the search (pole_refit.hpp)
  int search_steps = 0;                      ///< Levenberg–Marquardt steps of the chosen start
  /// Relative RMS residual of the best candidate with sampled poles (before the pole search).
  double sampled_poles_relative_rms_residual = 0.0;
  /// Why passivity costs more than kCostRatio in residual (empty otherwise): where the best sample is not
  /// passive, whether the data are, and what the passive bound allows.
  std::string cost_reason;
  /// term_conditioning (model/multipole.hpp) of theta over the data frequencies, and of the best sample.
  double conditioning = 1.0;
  double best_sample_conditioning = 1.0;
  /// Above this conditioning fit warns (docs/passivity.md, "Conditioning"): 10 costs log2 10 = 3.3 of a q15
  /// table's 15 bits.
  static constexpr double kMaxConditioning = 10.0;
  /// An ill-conditioned estimate is replaced by the most likely certified one within kMaxConditioning when that
  /// fits within this factor of its relative RMS residual.
  static constexpr double kConditioningCost = 1.1;
  /// Why an estimate above kMaxConditioning was kept (conditioning against residual); empty otherwise.
  std::string conditioning_tradeoff;
  /// The passive bound of the data (numerics/passive_bound.hpp), when cost_reason was stated with it.
  std::optional<double> passive_bound_relative_rms_residual;
};

/// `candidates`: samples of the order in descending likelihood (θ packed as model/order.hpp); the first
/// kCandidates are tried. The residues are the MAP under the fit's Gaussian residue prior of `admittance_scale`
/// and Re G ≥ 0, with σ the best sample's RMS residual per real component (docs/passivity.md, "Under the residue
/// prior"). changed = false when the chosen one was passive as sampled. `starts` of the pole
/// search (0: the sampled poles only, as before the search existed; for measuring what it gains). `bound`, when
/// given, is the data's passive bound, asked for only when passivity costs more than kCostRatio.
PassiveEstimate passive_estimate(const Measurement& data, const Order& order,
                                 const std::vector<Eigen::VectorXd>& candidates, DataCount count,
                                 int starts = PassiveEstimate::kStarts, const LazyPassiveBound* bound = nullptr,
                                 double admittance_scale = kDefaultAdmittanceScale);

/// One line for the terminal and fit.json's warnings when the estimate's conditioning exceeds kMaxConditioning:
/// what it costs a fixed-point header and the fix. Empty otherwise.
std::string conditioning_warning(const Order& order, const PassiveEstimate& e);

/// Share of data points with Re y < 0 (a passive wall has Re y ≥ 0) and the most negative Re y.
struct DataPassivity {
  int negative_points = 0;
  double min_re = 0.0;
};
DataPassivity data_passivity(const Measurement& data);

/// Whether a passive estimate with this residual is what passivity allows on the data: within kCostRatio of the
/// data's passive bound (docs/passivity.md, "The passive bound").
inline bool at_passive_bound(double estimate_rms, double bound_rms) {
  return estimate_rms <= PassiveEstimate::kCostRatio * bound_rms;
}

/// One line for the terminal and fit.json's warnings when the estimate costs more than kCostRatio: the cost
/// in nats and in RMS residual, and cost_reason. Empty when it costs less.
std::string passivity_cost_warning(const Order& order, const PassiveEstimate& e);

}  // namespace admitgen::passivity

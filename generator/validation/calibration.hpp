// SPDX-License-Identifier: MIT
/// @file
/// Simulation-based calibration of the fit (Talts, Betancourt, Simpson, Vehtari & Gelman 2018,
/// arXiv:1804.06788; docs/validation.md, "Calibration"). Each replicate draws θ from the prior restricted to
/// physically plausible models, simulates data, fits the true order with the library call of `fit`
/// (selection/fit.hpp fit_order) and records the rank of every true parameter among L posterior draws.
/// If the posterior is the exact Bayesian posterior of the generating model, every rank is uniform on
/// {0, …, L}.
///
/// The generating model and how the fit's posterior is made exactly its posterior:
///  - θ ~ the unreduced prior band_priors(grid) restricted to the plausible set R (plausible() below) by
///    rejection;
///  - complex noise of std σ_c = c·rms|G(θ)| on the grid, c log-uniform on [c_lo, c_hi] (σ_c/√2 per real
///    component, the likelihood's σ);
///  - the fit samples band_priors(grid) (no R) with the Jeffreys prior dσ/σ marginalised. Given θ the
///    generating model's σ has density 1/(σ ln(c_hi/c_lo)) on [c_lo, c_hi]·r(θ)/√2, i.e. Jeffreys truncated
///    to that interval, so its posterior is the fit's times 1_R(θ) · P(σ ∈ that interval | θ, D), where
///    S/σ² ~ χ²_K under Jeffreys (S the residual sum of squares of θ, K = 2N). generative_weights()
///    applies both factors to the run's points: an exact reweighting, not an approximation.
///  - Ranks are compared in the reporting fold the fit applies to its samples (priors.hpp
///    fold_to_reduced: λ ascending, β ≥ 0, pairs by β): the truth is folded the same way. The rank of
///    f(θ_true) among f(θ_draws) is uniform for any function f, so the fold keeps SBC exact; it only
///    removes the label-switching copies.
#pragma once

#include "data/measurement.hpp"
#include "inference/priors.hpp"
#include "model/order.hpp"
#include "selection/fit.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace admitgen::validation {

/// A measurement grid: `points` log-spaced frequencies from f_lo to f_hi (Hz).
struct Grid {
  std::string name;
  double f_lo_hz = 100.0;
  double f_hi_hz = 4000.0;
  int points = 150;
  Eigen::ArrayXd f_hz() const;
};
/// The impedance-tube band of the Table 1 priors: 100 Hz–4 kHz, 150 points.
Grid tube_grid();
/// A wide band: 50 Hz–10 kHz, 200 points.
Grid wide_grid();

/// The prior of the calibration runs on `grid`. Under the Gaussian residue prior (`base.residues`, the
/// default) it is the fit's default for data on that grid, PriorRanges::band(ω_hi) with base's admittance scale:
/// SBC then checks exactly what `fit` runs. Under the uniform prior it is Table 1 (`base`) with the pole ranges clipped to the band,
/// λ ∈ [ω_lo, min(λ_hi, ω_hi)], α ∈ [0, min(α_hi, ω_hi)], β ∈ ±min(β_hi, ω_hi) (ω = 2πf). Both the simulation
/// and the fit use it (a fit with `--priors`): a real pole above the band is indistinguishable from G∞ plus
/// a broad pair, and with Table 1's λ up to 75 000 s⁻¹ most of the posterior mass of such data would lie in
/// that out-of-band copy, outside R, leaving few points in R (the effective sample size of the reweighting).
PriorRanges band_priors(const Grid& grid, const PriorRanges& base = PriorRanges::table1());
/// The default `base` of the validation runs: the Gaussian residue prior of admittance scale
/// kDefaultAdmittanceScale (its pole ranges are replaced per grid by band_priors).
inline PriorRanges default_base_priors() { return PriorRanges::band(1.0); }

/// The plausible set R: every pole's natural frequency (λ_q, √(α_s² + β_s²)) inside the grid's band,
/// the model passive (model/passivity.hpp is_passive, exact), and kMinAbsG ≤ |G| ≤ kMaxAbsG at every grid
/// point (normal-incidence admittances of real absorbers lie in 0.02-3). Invariant under the label
/// symmetries, so it commutes with every fold.
constexpr double kMinAbsG = 0.01;
constexpr double kMaxAbsG = 5.0;
bool plausible(const Order& order, const double* theta, const Eigen::ArrayXd& omega);
/// The natural frequencies R admits, [lo, hi] (rad/s).
struct PoleWindow {
  double lo = 0.0, hi = 0.0;
};
/// The grid's band: what plausible() above uses.
PoleWindow band_window(const Eigen::ArrayXd& omega);
/// Every natural frequency the prior holds, [0, max(λ_hi, |α_hi + jβ_hi|)]: R then restricts to passive models
/// of bounded |G| only. SBC of the band prior uses it, whose poles reach 4 ω_max: with the band window most fits
/// put a third of their mass on out-of-band poles that the reweighting to R discards (docs/validation.md,
/// "Calibration").
PoleWindow prior_window(const PriorRanges& priors);
bool plausible(const Order& order, const double* theta, const Eigen::ArrayXd& omega, const PoleWindow& window);

/// One simulated data set.
struct Simulation {
  Order order{0, 0};
  Eigen::VectorXd theta;  ///< the truth, folded as the fit reports (fold_to_reduced)
  Grid grid;
  double noise = 0.0;     ///< c: complex noise std relative to rms|G(θ)| on the grid
  double sigma = 0.0;     ///< σ_c = c·rms|G(θ)|, the complex noise std
  long prior_draws = 0;   ///< prior draws until one was plausible
  PoleWindow window;      ///< the natural frequencies R admitted
  Measurement data;
};

/// θ from the prior `ranges` restricted to R (rejection, at most 10^7 draws: InternalError beyond), c
/// log-uniform on [noise_lo, noise_hi] (noise_lo = noise_hi: fixed), data on `grid`; all from `seed`.
/// `accept`, when given, restricts R further (a predicate of θ, unfolded, and of the grid's ω; it must be
/// invariant under the label symmetries too).
using SimulationFilter = std::function<bool(const double* theta, const Eigen::ArrayXd& omega)>;
Simulation simulate(const Order& order, const Grid& grid, double noise_lo, double noise_hi,
                    const PriorRanges& ranges, std::uint64_t seed, const SimulationFilter& accept = {},
                    const std::optional<PoleWindow>& window = std::nullopt);  ///< default: the grid's band

/// Posterior weights of the run's points under the generating model (see the file comment): the run's
/// weights × 1_R(θ_i) × P(σ ∈ [noise_lo, noise_hi]·r(θ_i)/√2 | θ_i, D); normalised (sum 1). The run's θ
/// must be folded the same way as sim.theta.
Eigen::ArrayXd generative_weights(const Simulation& sim, double noise_lo, double noise_hi, const NestedRun& run);

/// The parameter families reported: G∞, the real poles (A, λ), the pair residues (B, C), the pair poles (α, β).
enum class ReportFamily { g_inf, real_pole, pair_residue, pair_pole };
ReportFamily report_family(Family f);
std::string family_label(ReportFamily f);  ///< "G_inf", "A/lambda", "B/C", "alpha/beta"

struct SbcSettings {
  int replicates = 100;
  std::vector<Order> orders{Order(1, 1), Order(0, 2), Order(0, 1), Order(1, 2)};  ///< replicate i: orders[i % size]
  std::vector<Grid> grids{tube_grid(), wide_grid()};  ///< replicate i: grids[(i / orders) % size]
  double noise_lo = 0.003, noise_hi = 0.03;
  int live = 100;
  /// L posterior draws per replicate (ranks 0..L); L + 1 a multiple of 40 so that the central 50 % and
  /// 95 % rank sets are exactly nominal.
  int draws = 199;
  std::vector<SamplerKind> samplers{SamplerKind::poles};
  std::uint64_t seed = 1;
  int threads = 0;
  PriorRanges base_priors = default_base_priors();  ///< made each grid's prior by band_priors
};

struct ParameterRank {
  std::string name;
  Family family = Family::g_inf;
  double truth = 0.0;
  int rank = 0;              ///< draws below the truth, 0..L
  double mean = 0.0, std = 0.0;  ///< the fit's own posterior summary (fit.json)
  double passive_z = 0.0;    ///< (passive estimate − mean)/std
};

struct SbcReplicate {
  int index = 0;
  Order order{0, 0};
  std::string grid;
  double noise = 0.0;
  long prior_draws = 0;
  std::string sampler;        ///< "full" | "poles" (asked for)
  std::string sampler_used;   ///< ModelResult::sampler (the pole sampler may fall back to full)
  double log_z = 0.0;
  /// ln L (the fit's σ-marginal likelihood) at the truth and the best the run found: a truth far above the
  /// run's best means the sampler missed the truth's mode.
  double log_l_truth = 0.0, max_log_l = 0.0;
  double ess = 0.0;           ///< Kish ESS of the generative weights
  double outside_mass = 0.0;  ///< the fit's posterior mass outside R
  bool passive_changed = false;
  std::vector<ParameterRank> ranks;
};

/// Runs every replicate with every sampler (in parallel over `threads`; each task on its own seed stream,
/// so the result does not depend on the thread count), ordered by replicate, then sampler.
/// `done` (optional) is called after each task, from the worker, under no lock.
std::vector<SbcReplicate> run_sbc(const SbcSettings& settings,
                                  const std::function<void(const SbcReplicate&)>& done = {});

/// Rank set membership for L draws: central 50 % and 95 % (exact when (L + 1) % 40 == 0).
bool in_central(int rank, int draws, double level);

/// χ² statistic of a rank histogram with `bins` equal bins over {0..L} ((L + 1) % bins == 0), and its
/// upper-tail p-value with bins − 1 degrees of freedom.
struct Uniformity {
  int n = 0;
  int bins = 0;
  double chi2 = 0.0;
  double p_value = 1.0;
  std::vector<int> counts;
};
Uniformity rank_uniformity(const std::vector<int>& ranks, int draws, int bins);

struct FamilySummary {
  std::string sampler;
  ReportFamily family = ReportFamily::g_inf;
  int replicates = 0;           ///< replicates with at least one parameter of the family
  int instances = 0;            ///< parameter values ranked
  double coverage50 = 0.0, coverage95 = 0.0;  ///< pooled over instances
  Uniformity pooled;            ///< histogram of all ranks of the family (correlated within a replicate)
  /// Uniformity per parameter name (independent over replicates); the family's p-value is the smallest
  /// times the number tested (Bonferroni), over parameters with at least 5 expected per bin.
  double p_value = 1.0;
  std::string worst_parameter;
  int parameters_tested = 0;
  double passive_abs_z_median = 0.0, passive_abs_z_p90 = 0.0;
};
std::vector<FamilySummary> summarize_sbc(const std::vector<SbcReplicate>& replicates, int draws, int bins);

}  // namespace admitgen::validation

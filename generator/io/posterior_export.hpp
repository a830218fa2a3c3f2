// SPDX-License-Identifier: MIT
/// @file
/// The posterior where notebooks can read it (docs/posterior_files.md). Beside fit.json, which names
/// the index in its key "posterior":
///   posterior.json      schema "admitgen.posterior/1": per order the parameter names, the posterior
///                       mean and covariance (from the weighted nested-sampling points), the Kish
///                       effective sample size and the name of the order's samples file;
///   posterior_QxSy.csv  equally weighted posterior samples of that order, one row per draw, a header
///                       of parameter names (fit.json names, reduced form: β ≥ 0, λ and β ascending);
///   predictive.csv      the data with the selected order's model-curve median and 95 % posterior band
///                       of Re G, Im G and α (the numbers of fit.json's "predictive").
/// Numbers print with 17 significant digits (they read back exactly); files depend only on the runs
/// and the seed, never on the thread count.
#pragma once

#include "data/measurement.hpp"
#include "inference/nested_sampler.hpp"
#include "selection/fit.hpp"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace admitgen {

/// Name of the index file; fit.json's "posterior" key holds it.
inline constexpr const char* kPosteriorIndexFile = "posterior.json";

/// Posterior covariance Σ p_i (θ_i − μ)(θ_i − μ)ᵀ over every point of the run, p_i the normalised
/// nested-sampling weights (inference/posterior.hpp), μ = Σ p_i θ_i.
Eigen::MatrixXd posterior_covariance(const NestedRun& run, Eigen::VectorXd& mean);

/// Equally weighted samples of a run, one row per draw: round(Kish ESS) draws (at least 1) by systematic
/// resampling of the weights with `seed`. More draws than the ESS would only repeat points.
Eigen::MatrixXd equal_weight_samples(const NestedRun& run, std::uint64_t seed);

/// (file name, content) of every file listed above, the index first.
std::vector<std::pair<std::string, std::string>> posterior_export_files(const Measurement& data,
                                                                       const FitSettings& settings,
                                                                       const FitResult& fit);

/// Writes posterior_export_files into `dir`, each atomically; returns the index's file name.
std::string write_posterior_export(const std::string& dir, const Measurement& data, const FitSettings& settings,
                                   const FitResult& fit);

}  // namespace admitgen

/// @file
/// The passive estimate of a fitted order (docs/passivity.md, "Passive estimate"): the poles of the
/// highest-likelihood posterior sample, and the residues that fit the data best (the likelihood's own
/// unweighted least squares) among those that make Re G(jω) ≥ 0 at every ω (passivity/passive_residues.hpp).
/// It is what `emit` uses by default: a filter that is passive by construction, at the smallest possible
/// cost in fit for those poles.
#pragma once

#include "data/measurement.hpp"
#include "inference/likelihood.hpp"
#include "model/order.hpp"

#include <Eigen/Core>

#include <string>

namespace admitgen::passivity {

struct PassiveEstimate {
  static constexpr const char* kPolesFrom = "max_likelihood_sample";
  Eigen::VectorXd theta;                     ///< packed as model/order.hpp
  double log_likelihood = 0.0;               ///< ln L of theta (inference/likelihood.hpp)
  double relative_rms_residual = 0.0;        ///< √(Σ|D − G|² / Σ|D|²) of theta
  double best_sample_relative_rms_residual = 0.0;  ///< the same for the highest-likelihood sample
  double best_sample_log_likelihood = 0.0;
  bool certified = false;                    ///< Hamiltonian test: Re G ≥ 0 for every ω
  double min_re = 0.0;                       ///< minimum of Re G found by the certificate's scan
  int rounds = 0;                            ///< constraint-generation rounds
  bool changed = false;                      ///< false when the best sample was already passive and kept
};

/// `best` is the highest-likelihood sample of the order (θ packed as model/order.hpp). When it is
/// already passive it is returned unchanged (changed = false); otherwise its residues are refitted.
PassiveEstimate passive_estimate(const Measurement& data, const Order& order, const Eigen::VectorXd& best,
                                 DataCount count);

/// Share of data points with Re y < 0 (a passive wall has Re y ≥ 0) and the most negative Re y.
struct DataPassivity {
  int negative_points = 0;
  double min_re = 0.0;
};
DataPassivity data_passivity(const Measurement& data);

}  // namespace admitgen::passivity

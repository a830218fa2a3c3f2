// SPDX-License-Identifier: MIT
/// @file
/// Likelihood of an effect model given the measured admittance: complex Gaussian noise of unknown
/// std σ, scaled per point by the model's noise shape s_i (1 unless the model is heteroscedastic
/// noise), with σ marginalised under a Jeffreys prior p(σ) ∝ 1/σ — the same marginal-Gaussian
/// likelihood as `fit` (inference/likelihood.hpp), with weights. Each complex point holds K/N = 2 real
/// data of variance σ² s_i²:
///
///   L = ∫ Π_k (2π σ² s_k²)^{−1/2} e^{−ε_k²/(2σ² s_k²)} dσ/σ
///   ln L = ln Γ(K/2) − ln 2 − (K/2) ln(π E_w) − 2 Σ_i ln s_i,   E_w = Σ_i |y_i − ŷ_i|²/s_i²,  K = 2N.
///
/// The no-effect model has no free parameter, so its evidence is its likelihood: ln Z₀ = ln L(y_sim).
#pragma once

#include "diagnosis/effect_candidates.hpp"
#include "inference/likelihood.hpp"

#include <Eigen/Core>

namespace admitgen::diagnosis {

class EffectLikelihood {
 public:
  explicit EffectLikelihood(Eigen::ArrayXcd y_real);
  /// ln L of a prediction (noise_shape empty = all ones); a non-finite prediction gives −∞.
  double operator()(const EffectPrediction& prediction) const;

 private:
  Eigen::ArrayXcd y_;
  MarginalGaussian marginal_;  ///< K = 2N
};

}  // namespace admitgen::diagnosis

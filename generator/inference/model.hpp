// SPDX-License-Identifier: MIT
/// @file
/// What the sampler compares: a model is its parameter names, a prior transform from the unit cube, a
/// log-likelihood and, optionally, a symmetry fold. Model orders (selection/fit.hpp, and the pole-only
/// form in inference/poles_sampler.hpp) and measurement effects (diagnosis/effect_identification.hpp)
/// are builders of this one type; the nested sampler (inference/nested_sampler.hpp) and the 1-D
/// quadrature (inference/quadrature_evidence.hpp) run it, and inference/evidence.hpp compares the
/// evidences. Nothing here knows about acoustics (docs/method.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace admitgen {

/// θ from u ∈ [0, 1]^dim.
using PriorTransformFn = std::function<void(const double* u, double* theta)>;
/// ln L(θ); −∞ marks a point outside the likelihood's support.
using LogLikelihoodFn = std::function<double(const double* theta)>;
/// Optional symmetry fold: maps u in place to its canonical copy, for a likelihood invariant under the
/// corresponding group (see inference/priors.hpp). Chains then move in the full cube and every accepted
/// point is folded back.
using FoldFn = std::function<void(double* u)>;

struct Model {
  std::vector<std::string> parameter_names;  ///< one per dimension of θ, in θ's order
  PriorTransformFn prior_transform;
  LogLikelihoodFn log_likelihood;
  FoldFn fold{};  ///< empty: no symmetry to fold

  int dim() const { return static_cast<int>(parameter_names.size()); }
};

}  // namespace admitgen

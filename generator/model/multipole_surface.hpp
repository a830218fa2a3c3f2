// SPDX-License-Identifier: MIT
/// @file
/// The fitted continuous model: a surface given directly by a multipole admittance (docs/method.md, paper eq. 2),
/// from explicit parameters or from a fit record (model/fit_record.hpp). Evaluated by
/// model/multipole.hpp; the packing of θ is the one of model/order.hpp.
#pragma once

#include "model/fit_record.hpp"
#include "model/order.hpp"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace admitgen {

struct MultipoleSurface {
  Order order;
  Eigen::VectorXd theta;  ///< packed as Order says: G_inf, A_1, lambda_1, …, B_1, C_1, alpha_1, beta_1, …
};

/// Whether a reader refuses a model whose poles are not all in the open left half-plane. Every consumer
/// that builds a filter refuses it (emit, synth, diagnose); `admitgen check` reads it and reports the
/// violation as its failing causality check (exit 1 rather than 2).
enum class Causality { required, reported };

/// What makes `surface` non-causal or marginally stable, one entry per pole (λ_q ≤ 0 or α_s ≤ 0, NaN
/// included), naming the parameter and its value; empty when every pole is in the open left half-plane
/// (docs/physics.md §2.1). The causality check and the readers' refusals share these words.
std::vector<std::string> causality_violations(const MultipoleSurface& surface);
/// Whether every pole of θ (packed as `order` says) is in the open left half-plane: λ_q > 0 and α_s > 0
/// (NaN fails); exactly when causality_violations lists nothing.
bool is_causal(const Order& order, const double* theta);

/// Builds θ from fit.json names (G_inf, A_q, lambda_q, B_s, C_s, alpha_s, beta_s). The order is the
/// one the names imply (Q = number of A_q, S = number of B_s); every parameter of that order must be
/// present and finite. Throws InputError naming the missing, surplus or non-finite name, or (when
/// causality is required) the first causality violation; `context` prefixes messages.
MultipoleSurface multipole_from_parameters(const std::map<std::string, double>& values, const std::string& context,
                                           Causality causality = Causality::required);

/// Which estimate of a fit to take as θ: the passive estimate (docs/passivity.md; best sample's poles,
/// residues refitted under Re G ≥ 0), the posterior mean, or the highest-likelihood sample.
enum class Estimate { passive, mean, max_likelihood };

/// "passive" | "mean" | "max_likelihood" (throws InputError otherwise) and back.
Estimate parse_estimate(const std::string& text);
const char* estimate_name(Estimate estimate);

/// True when the fit holds a passive estimate for `order` (empty: the selected one); fits written by
/// older versions of admitgen do not.
/// Throws InputError naming `origin` if `order` was not fitted.
bool fit_has_passive_estimate(const FitRecord& fit, const std::string& order, const std::string& origin);

/// The multipole of a fit: the selected order by default, or `order` (e.g. "Q0S2") from its models.
/// Throws InputError naming `origin` if the fit lacks that order or estimate, or (when causality is
/// required) naming the parameter that makes it non-causal.
MultipoleSurface multipole_from_fit(const FitRecord& fit, const std::string& order, Estimate estimate,
                                    const std::string& origin, Causality causality = Causality::required);

/// y(f) = G(2πf) at f_hz.
Eigen::ArrayXcd surface_admittance(const MultipoleSurface& surface, const Eigen::ArrayXd& f_hz);

}  // namespace admitgen

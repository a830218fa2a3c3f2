/// @file
/// A surface given directly by a multipole admittance (method.md eq. 2), from explicit parameters or
/// from a `fit.json` written by `admitgen fit`. Evaluated by model/multipole.hpp; the packing of θ is
/// the one of model/order.hpp.
#pragma once

#include "model/order.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace admitgen {

struct MultipoleSurface {
  Order order;
  Eigen::VectorXd theta;  ///< packed as Order says: G_inf, A_1, lambda_1, …, B_1, C_1, alpha_1, beta_1, …
};

/// Builds θ from contract names (G_inf, A_q, lambda_q, B_s, C_s, alpha_s, beta_s). The order is the
/// one the names imply (Q = number of A_q, S = number of B_s); every parameter of that order must be
/// present. Throws InputError naming the missing or surplus name; `context` prefixes messages.
MultipoleSurface multipole_from_parameters(const std::map<std::string, double>& values, const std::string& context);

/// Which estimate of a fit to take as θ: the passive estimate (docs/passivity.md; best sample's poles,
/// residues refitted under Re G ≥ 0), the posterior mean, or the highest-likelihood sample.
enum class Estimate { passive, mean, max_likelihood };

/// "passive" | "mean" | "max_likelihood" (throws InputError otherwise) and back.
Estimate parse_estimate(const std::string& text);
const char* estimate_name(Estimate estimate);

/// True when the fit holds a passive estimate for `order` (empty: the selected one); fits written by
/// older versions of admitgen do not.
bool fit_has_passive_estimate(const nlohmann::json& fit, const std::string& order, const std::string& origin);

/// The multipole of a parsed fit.json (schema admitgen.fit/1): the selected order by default, or
/// `order` (e.g. "Q0S2") from its "models" list. Throws InputError naming `origin` if the document
/// lacks what is needed.
MultipoleSurface multipole_from_fit(const nlohmann::json& fit, const std::string& order, Estimate estimate,
                                    const std::string& origin);

/// y(f) = G(2πf) at f_hz.
Eigen::ArrayXcd surface_admittance(const MultipoleSurface& surface, const Eigen::ArrayXd& f_hz);

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "model/multipole_surface.hpp"

#include "core/errors.hpp"
#include "model/multipole.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <algorithm>

namespace admitgen {
namespace {

int count_indexed(const std::map<std::string, double>& values, const std::string& prefix) {
  int n = 0;
  while (values.count(fmt::format("{}_{}", prefix, n + 1)) != 0) ++n;
  return n;
}

/// The model of `order` (empty: the selected one); throws InputError if it was not fitted.
const FitModel& model_entry(const FitRecord& fit, const std::string& order, const std::string& origin) {
  if (const FitModel* m = fit.model(order)) return *m;
  throw InputError(fmt::format("{}: order {} was not fitted", origin, order.empty() ? fit.selected_order : order));
}

}  // namespace

Estimate parse_estimate(const std::string& text) {
  if (text == "passive") return Estimate::passive;
  if (text == "mean") return Estimate::mean;
  if (text == "max_likelihood") return Estimate::max_likelihood;
  throw InputError(fmt::format("estimate '{}' is not one of passive, mean, max_likelihood", text));
}

const char* estimate_name(Estimate estimate) {
  switch (estimate) {
    case Estimate::passive: return "passive";
    case Estimate::mean: return "mean";
    case Estimate::max_likelihood: return "max_likelihood";
  }
  return "?";
}

bool fit_has_passive_estimate(const FitRecord& fit, const std::string& order, const std::string& origin) {
  return model_entry(fit, order, origin).passive_estimate.has_value();
}

bool is_causal(const Order& order, const double* theta) {
  for (int q = 0; q < order.q(); ++q)
    if (!(theta[Order::lambda(q)] > 0.0)) return false;
  for (int k = 0; k < order.s(); ++k)
    if (!(theta[order.alpha(k)] > 0.0)) return false;
  return true;
}

std::vector<std::string> causality_violations(const MultipoleSurface& surface) {
  const Order& o = surface.order;
  const auto& th = surface.theta;
  std::vector<std::string> violations;
  for (int q = 0; q < o.q(); ++q)
    if (!(th[Order::lambda(q)] > 0.0))
      violations.push_back(fmt::format("lambda_{} = {:.6g} 1/s is not positive: the kernel A e^(-lambda t) grows "
                                       "(pole in the right half-plane or on the axis)", q + 1, th[Order::lambda(q)]));
  for (int k = 0; k < o.s(); ++k)
    if (!(th[o.alpha(k)] > 0.0))
      violations.push_back(fmt::format("alpha_{} = {:.6g} 1/s is not positive: the pair's kernel grows "
                                       "(beta_{} = {:.6g} 1/s)", k + 1, th[o.alpha(k)], k + 1, th[o.beta(k)]));
  return violations;
}

MultipoleSurface multipole_from_parameters(const std::map<std::string, double>& values, const std::string& context,
                                           Causality causality) {
  const Order order(count_indexed(values, "A"), count_indexed(values, "B"));
  const auto names = order.parameter_names();
  Eigen::VectorXd theta(order.dim());
  for (int i = 0; i < order.dim(); ++i) {
    const auto it = values.find(names[static_cast<std::size_t>(i)]);
    if (it == values.end())
      throw InputError(fmt::format("{}: {} needs parameter '{}' (all of: {})", context, order.name(),
                                   names[static_cast<std::size_t>(i)], fmt::join(names, ", ")));
    if (!std::isfinite(it->second))
      throw InputError(fmt::format("{}: parameter '{}' is not a finite number ({})", context, it->first, it->second));
    theta[i] = it->second;
  }
  for (const auto& [name, value] : values)
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw InputError(fmt::format("{}: '{}' is not a parameter of {} (expected: {})", context, name, order.name(),
                                   fmt::join(names, ", ")));
  MultipoleSurface surface{order, theta};
  if (causality == Causality::required)
    if (const auto violations = causality_violations(surface); !violations.empty())
      throw UnsafeModelError(fmt::format("{}: unsafe model, check 'causality' fails: {} (admitgen check names every failing "
                                   "check)", context, violations.front()));
  return surface;
}

MultipoleSurface multipole_from_fit(const FitRecord& fit, const std::string& order, Estimate estimate,
                                    const std::string& origin, Causality causality) {
  const FitModel& m = model_entry(fit, order, origin);
  std::map<std::string, double> values;
  if (estimate == Estimate::passive) {
    if (!m.passive_estimate)
      throw InputError(fmt::format("{}: order {} has no passive estimate (written by an older admitgen): re-run "
                                   "admitgen fit, or choose {} mean or max_likelihood",
                                   origin, m.order, setting("estimate")));
    for (const auto& [name, v] : m.passive_estimate->parameters) values[name] = v;
    return multipole_from_parameters(values, origin, causality);
  }
  // The selected order's summaries are the top-level "parameters" of the file (the same numbers).
  const bool selected = order.empty() || Order::parse(order) == Order::parse(fit.selected_order);
  for (const auto& p : selected ? fit.parameters : m.parameters)
    values[p.name] = estimate == Estimate::mean ? p.mean : p.max_likelihood;
  return multipole_from_parameters(values, origin, causality);
}

Eigen::ArrayXcd surface_admittance(const MultipoleSurface& surface, const Eigen::ArrayXd& f_hz) {
  return evaluate_multipole(surface.order, surface.theta, 2.0 * EIGEN_PI * f_hz);
}

}  // namespace admitgen

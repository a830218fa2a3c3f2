// SPDX-License-Identifier: MIT
#include "selection/goodness_of_fit.hpp"

#include "core/errors.hpp"
#include "inference/posterior.hpp"
#include "model/multipole.hpp"

#include <fmt/format.h>

#include <cmath>

namespace admitgen {

GoodnessOfFit goodness_of_fit(const Measurement& data, const ModelResult& model) {
  Eigen::ArrayXd re, im;
  evaluate_multipole(model.order, model.run.point(max_likelihood_index(model.run)), data.omega(), re, im);
  Eigen::ArrayXcd g(data.size());
  g.real() = re;
  g.imag() = im;
  GoodnessOfFit out;
  out.relative_rms = std::sqrt((data.y - g).abs2().sum() / data.y.abs2().sum());
  out.max_abs_delta_alpha = (absorption(data.y) - absorption(g)).abs().maxCoeff();
  return out;
}

std::optional<std::string> poor_fit_warning(const std::string& order, const GoodnessOfFit& g) {
  if (!(g.relative_rms > kPoorRelativeRms) && !(g.max_abs_delta_alpha > kPoorDeltaAlpha)) return std::nullopt;
  return fmt::format("{} fits poorly: relative RMS residual {:.3g} (threshold {}), max |delta alpha| {:.3g} "
                     "(threshold {}); check how the data were read ({}, {}, {}) or allow a larger order",
                     order, g.relative_rms, kPoorRelativeRms, g.max_abs_delta_alpha, kPoorDeltaAlpha,
                     setting("quantity"), setting("rho_c"), setting("time_convention"));
}

}  // namespace admitgen

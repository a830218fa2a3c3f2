// SPDX-License-Identifier: MIT
#include "selection/fit.hpp"

#include "core/errors.hpp"
#include "inference/comparison.hpp"
#include "model/multipole.hpp"
#include "selection/accuracy_stop.hpp"
#include "selection/grid_growth.hpp"
#include "selection/missed_modes.hpp"
#include "selection/order_marginals.hpp"
#include "selection/order_runs.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace admitgen {

PredictiveBand predictive_band(const Measurement& data, const ModelResult& model, int draws, std::uint64_t seed) {
  Rng rng(seed);
  const auto idx = resample_indices(posterior_weights(model.run), static_cast<std::size_t>(draws), rng);
  const Eigen::ArrayXd omega = data.omega();
  const Eigen::Index n = omega.size();
  Eigen::ArrayXXd re(n, draws), im(n, draws), al(n, draws);
  Eigen::ArrayXd r, i;
  for (int d = 0; d < draws; ++d) {
    evaluate_multipole(model.order, model.run.point(idx[static_cast<std::size_t>(d)]), omega, r, i);
    re.col(d) = r;
    im.col(d) = i;
    Eigen::ArrayXcd g(n);
    g.real() = r;
    g.imag() = i;
    al.col(d) = absorption(g);
  }
  const Eigen::ArrayXd equal = Eigen::ArrayXd::Constant(draws, 1.0);
  PredictiveBand band;
  band.f_hz = data.f_hz;
  band.draws = draws;
  const auto quantiles = [&](const Eigen::ArrayXXd& m, Eigen::ArrayXd& lo, Eigen::ArrayXd& med, Eigen::ArrayXd& hi) {
    lo.resize(n), med.resize(n), hi.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const Eigen::ArrayXd row = m.row(k).transpose();
      lo[k] = weighted_quantile(row, equal, 0.025);
      med[k] = weighted_quantile(row, equal, 0.5);
      hi[k] = weighted_quantile(row, equal, 0.975);
    }
  };
  quantiles(re, band.re_lo, band.re_median, band.re_hi);
  quantiles(im, band.im_lo, band.im_median, band.im_hi);
  quantiles(al, band.alpha_lo, band.alpha_median, band.alpha_hi);
  return band;
}

namespace {

/// The largest order of the grid (Q = qmax, S = smax) must have fewer parameters than real data.
void check_constrainable(const Measurement& data, const FitSettings& settings) {
  const Order largest(settings.qmax, settings.smax);
  const int k = real_data_count(settings.data_count, data.size());
  if (k < largest.dim() + 2)
    throw InputError(fmt::format("{} has {} parameters but the data hold only K = {} real values; lower "
                                 "{}/{} or supply more frequency points",
                                 largest.name(), largest.dim(), k, setting("qmax"), setting("smax")));
}

}  // namespace


std::vector<Eigen::VectorXd> best_samples(const ModelResult& model, int n) {
  const NestedRun& run = model.run;
  std::vector<std::size_t> idx(run.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  const std::size_t k = std::min(idx.size(), static_cast<std::size_t>(std::max(n, 0)));
  // Ties broken by index, so the choice is deterministic.
  std::partial_sort(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(k), idx.end(), [&](std::size_t a, std::size_t b) {
    return run.log_likelihood[a] > run.log_likelihood[b] || (run.log_likelihood[a] == run.log_likelihood[b] && a < b);
  });
  std::vector<Eigen::VectorXd> out;
  for (std::size_t i = 0; i < k; ++i)
    out.emplace_back(Eigen::Map<const Eigen::VectorXd>(run.point(idx[i]), model.order.dim()));
  return out;
}

FitResult run_fit(const Measurement& data, const FitSettings& settings, Progress& progress) {
  return complete_fit(data, settings, run_first_round(data, settings, progress), progress);
}

std::vector<ModelResult> run_first_round(const Measurement& data, const FitSettings& given, Progress& progress) {
  const FitSettings settings = with_band_priors(given, data);
  const std::vector<Order> grid = order_grid(settings.qmax, settings.smax);
  check_constrainable(data, settings);
  check_runs(settings);
  FittedOrders orders{grid, std::vector<ModelResult>(grid.size(), ModelResult{Order(0, 0), {}, 0, 0.0, {}}),
                      std::vector<int>(grid.size(), 0)};
  std::vector<std::size_t> which(grid.size());
  std::iota(which.begin(), which.end(), std::size_t{0});
  run_orders(data, settings, orders, which, progress);
  return std::move(orders.results);
}

FitResult complete_fit(const Measurement& data, const FitSettings& given, std::vector<ModelResult> results,
                       Progress& progress) {
  const FitSettings settings = with_band_priors(given, data);
  std::vector<Order> grid = order_grid(settings.qmax, settings.smax);
  check_constrainable(data, settings);
  if (results.size() != grid.size())
    throw std::logic_error("complete_fit: one first-round result per order of the grid expected");
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (results[i].order != grid[i]) throw std::logic_error("complete_fit: results not in grid order");
  double first_round_passes = 0.0;
  for (const auto& m : results)
    first_round_passes += pole_passes(m.order, static_cast<double>(m.run.calls), static_cast<long>(data.size()));
  const std::size_t n = grid.size();
  FittedOrders orders{std::move(grid), std::move(results), std::vector<int>(n, 0)};
  OrderMarginals marginals(data, settings.data_count, settings.priors.admittance_scale);
  rerun_missed_modes(data, settings, orders, marginals, progress);

  FitResult fit;
  const passivity::LazyPassiveBound bound(data);
  bool would_grow = false;
  fit.grid = grow_grid(data, settings, orders, marginals, first_round_passes, bound, would_grow, progress);
  estimate_passive(data, settings, orders.results, bound);
  fit.selected = select_usable(settings, orders.results);
  fit.models = std::move(orders.results);
  const std::vector<MissedMode> missed = missed_modes(data, settings, fit.models, marginals);
  fit.warnings = missed_mode_warnings(fit.models, missed);
  fit.notes = missed_mode_notes(fit.models, missed);
  if (settings.runs > 1)
    for (std::string& w : runs_disagree_warnings(fit.models)) fit.warnings.push_back(std::move(w));
  if (!fit.grid.edge.empty()) fit.warnings.push_back(fit.grid.edge);
  if (auto note = target_met_note(data, settings, fit.models, fit.selected, would_grow); !note.empty())
    fit.notes.push_back(std::move(note));
  if (auto w = target_missed_warning(data, settings, fit.models, fit.selected, bound); !w.empty()) fit.warnings.push_back(std::move(w));
  if (const auto w = passivity::passivity_cost_warning(fit.models[fit.selected].order, fit.models[fit.selected].passive);
      !w.empty())
    fit.warnings.push_back(w);
  if (const auto w = passivity::conditioning_warning(fit.models[fit.selected].order, fit.models[fit.selected].passive);
      !w.empty())
    fit.warnings.push_back(w);
  if (const auto d = passivity::data_passivity(data); d.negative_points > 0)
    fit.warnings.push_back(fmt::format(
        "the data are not passive at {} of {} points (Re y down to {:.3g}; a wall cannot return more energy than it "
        "receives): noise on a nearly rigid sample, or a calibration error; every passive estimate is the closest "
        "passive model to these data",
        d.negative_points, data.size(), d.min_re));
  constexpr int kPredictiveDraws = 1000;
  fit.predictive = predictive_band(data, fit.models[fit.selected], kPredictiveDraws,
                                   derive_seed(settings.sampler.seed, 0xbadULL));
  return fit;
}

}  // namespace admitgen

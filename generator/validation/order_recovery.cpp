// SPDX-License-Identifier: MIT
#include "validation/order_recovery.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "inference/likelihood.hpp"
#include "inference/posterior.hpp"
#include "model/multipole.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen::validation {

std::vector<Order> RecoverySettings::order_range(int q0, int q1, int s0, int s1) {
  std::vector<Order> out;
  for (int q = q0; q <= q1; ++q)
    for (int s = s0; s <= s1; ++s) out.emplace_back(q, s);
  return out;
}

bool is_competitor(const Order& order, const Order& truth) {
  const bool contains_truth = order.q() >= truth.q() && order.s() >= truth.s();
  return !contains_truth && order.q() + order.s() <= truth.q() + truth.s();
}

bool distinct_terms(const Order& order, const double* theta, const Eigen::ArrayXd& omega) {
  std::vector<double> natural;
  for (int q = 0; q < order.q(); ++q) natural.push_back(theta[Order::lambda(q)]);
  for (int s = 0; s < order.s(); ++s) {
    const double w0 = std::hypot(theta[order.alpha(s)], theta[order.beta(s)]);
    if (!(w0 >= 2.0 * kMinPairQuality * theta[order.alpha(s)])) return false;
    natural.push_back(w0);
  }
  std::sort(natural.begin(), natural.end());
  for (std::size_t k = 1; k < natural.size(); ++k)
    if (!(natural[k] >= kDistinctRatio * natural[k - 1])) return false;
  Eigen::ArrayXd re, im;
  evaluate_multipole(order, theta, omega, re, im);
  const double norm_g = std::sqrt((re.square() + im.square()).sum());
  const auto share = [&](const Order& term, const double* th) {
    evaluate_multipole(term, th, omega, re, im);
    return std::sqrt((re.square() + im.square()).sum()) / norm_g;
  };
  for (int q = 0; q < order.q(); ++q) {
    const double th[3] = {0.0, theta[Order::a(q)], theta[Order::lambda(q)]};
    if (!(share(Order(1, 0), th) >= kMinTermShare)) return false;
  }
  for (int s = 0; s < order.s(); ++s) {
    const double th[5] = {0.0, theta[order.b(s)], theta[order.c(s)], theta[order.alpha(s)], theta[order.beta(s)]};
    if (!(share(Order(0, 1), th) >= kMinTermShare)) return false;
  }
  return true;
}

namespace {

RecoveryCase run_case(const RecoverySettings& settings, int index, SamplerKind kind) {
  const std::size_t per_truth = settings.noise.size() * static_cast<std::size_t>(settings.per_cell);
  const Order& truth = settings.truths[static_cast<std::size_t>(index) / per_truth];
  const double noise = settings.noise[(static_cast<std::size_t>(index) / static_cast<std::size_t>(settings.per_cell)) %
                                      settings.noise.size()];
  // Streams above those of run_sbc's replicates, so a recovery data set is never an SBC one.
  const std::uint64_t seed = derive_seed(settings.seed, 1'000'000u + static_cast<std::uint64_t>(index));
  // The fit runs the prior under test; the truths come from Table 1 clipped to the band (band_priors of the uniform
  // box), whose plausible draws are common: under the Gaussian residue prior, passive models with three or four
  // terms of random sign are too rare to draw by rejection (none of Q1S3 in 10 M draws). Recovery asks whether
  // `fit` finds the order of plausible data, not whether data follow its prior (that is SBC's question).
  const PriorRanges priors = band_priors(settings.grid, settings.base_priors);
  const PriorRanges truth_priors = band_priors(settings.grid, PriorRanges::table1());
  SimulationFilter accept;
  if (settings.design == RecoveryDesign::distinct)
    accept = [&truth](const double* th, const Eigen::ArrayXd& omega) { return distinct_terms(truth, th, omega); };
  const Simulation sim = simulate(truth, settings.grid, noise, noise, truth_priors, seed, accept);

  FitSettings fit;
  fit.qmax = settings.qmax;
  fit.smax = settings.smax;
  fit.grid_growth = 0;  // the map is over the stated grid, which holds every truth with a margin
  fit.priors = priors;
  fit.priors_origin = "validation priors of " + settings.grid.name;
  fit.sampler.live = settings.live;
  fit.runs = settings.runs;
  fit.sampler.seed = derive_seed(seed, 1);
  fit.sampler_kind = kind;
  fit.rule = settings.rule;
  fit.threads = 1;
  Progress quiet(false);
  const FitResult result = run_fit(sim.data, fit, quiet);

  RecoveryCase c;
  c.index = index;
  c.truth = truth;
  c.noise = noise;
  c.sampler = kind == SamplerKind::full ? "full" : "poles";
  c.selected = result.models[result.selected].order;
  c.extra_terms = (c.selected.q() + c.selected.s()) - (truth.q() + truth.s());
  for (const auto& m : result.models) {
    c.fallbacks += !m.sampler_note.empty() && kind == SamplerKind::poles;
    c.evidence.push_back({m.order, m.run.log_z, m.run.log_z_error, m.run.max_log_likelihood, m.sampler, m.live});
  }
  c.log_l_truth = Likelihood(sim.data, truth, DataCount::two_per_point)(sim.theta.data());
  c.data = sim.data;

  const Eigen::ArrayXd omega = sim.data.omega();
  const Eigen::ArrayXcd g_true = evaluate_multipole(truth, sim.theta, omega);
  // D over the competitors (see the file comment), and over the one-term-smaller orders alone.
  c.distance = c.distance_smaller = std::numeric_limits<double>::infinity();
  for (const auto& m : result.models) {
    const bool one_smaller = (m.order.q() == truth.q() - 1 && m.order.s() == truth.s()) ||
                             (m.order.q() == truth.q() && m.order.s() == truth.s() - 1);
    if (!is_competitor(m.order, truth)) continue;
    Eigen::ArrayXd re, im;
    evaluate_multipole(m.order, m.run.point(max_likelihood_index(m.run)), omega, re, im);
    const double d = std::sqrt(((g_true.real() - re).square() + (g_true.imag() - im).square()).sum()) / sim.sigma;
    if (one_smaller) c.distance_smaller = std::min(c.distance_smaller, d);
    if (d < c.distance) {
      c.distance = d;
      c.nearest = m.order;
    }
  }
  ADMITGEN_ENSURE(std::isfinite(c.distance_smaller), "no one-term-smaller order of {} in the fitted grid", truth.name());
  c.rms_sigma = c.distance / std::sqrt(static_cast<double>(sim.data.size()));
  c.identifiable = c.distance >= kIdentifiableDistance;
  return c;
}

}  // namespace

std::vector<RecoveryCase> run_recovery(const RecoverySettings& settings,
                                       const std::function<void(const RecoveryCase&)>& done) {
  for (const Order& t : settings.truths)
    ADMITGEN_ENSURE(t.q() <= settings.qmax && t.s() <= settings.smax && t.q() + t.s() >= 1,
                    "true order {} outside the fitted grid or without a term", t.name());
  const std::size_t n_samplers = settings.samplers.size();
  const int sets = static_cast<int>(settings.truths.size() * settings.noise.size()) * settings.per_cell;
  std::vector<int> indices = settings.cases;
  if (indices.empty())
    for (int i = 0; i < sets; ++i) indices.push_back(i);
  for (int i : indices)
    if (i < 0 || i >= sets)
      throw InputError(fmt::format("order recovery: data set {} does not exist (this design has 0-{})", i, sets - 1));
  std::vector<RecoveryCase> out(indices.size() * n_samplers);
  std::vector<std::size_t> queue(out.size());
  for (std::size_t t = 0; t < queue.size(); ++t) queue[t] = t;
  run_in_parallel(queue, settings.threads, [&](std::size_t t) {
    const int index = indices[t / n_samplers];
    try {
      out[t] = run_case(settings, index, settings.samplers[t % n_samplers]);
    } catch (const InternalError& e) {  // name the data set, so that it can be run alone
      throw InternalError(fmt::format("order recovery data set {} (seed {}): {}", index, settings.seed, e.what()));
    }
    if (done) done(out[t]);
  });
  return out;
}

}  // namespace admitgen::validation

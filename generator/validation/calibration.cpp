// SPDX-License-Identifier: MIT
#include "validation/calibration.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "inference/likelihood.hpp"
#include "inference/posterior.hpp"
#include "model/multipole.hpp"
#include "model/passivity.hpp"
#include "passivity/passive_estimate.hpp"

#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace admitgen::validation {

Eigen::ArrayXd Grid::f_hz() const {
  return Eigen::ArrayXd::LinSpaced(points, std::log(f_lo_hz), std::log(f_hi_hz)).exp();
}

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
}  // namespace

Grid tube_grid() { return {"100Hz-4kHz", 100.0, 4000.0, 150}; }
Grid wide_grid() { return {"50Hz-10kHz", 50.0, 10000.0, 200}; }

PriorRanges band_priors(const Grid& grid, const PriorRanges& base) {
  if (base.residues == ResiduePrior::gaussian) return PriorRanges::band(kTwoPi * grid.f_hi_hz, base.admittance_scale);
  const double w_lo = kTwoPi * grid.f_lo_hz, w_hi = kTwoPi * grid.f_hi_hz;
  PriorRanges p = base;
  p.lambda = {std::max(base.lambda.lo, w_lo), std::min(base.lambda.hi, w_hi)};
  p.alpha.hi = std::min(base.alpha.hi, w_hi);
  const double beta = std::min(std::max(-base.beta.lo, base.beta.hi), w_hi);
  p.beta = {-beta, beta};
  p.validate("band priors of " + grid.name);
  return p;
}

namespace {

/// rms |G| over the grid.
double rms_abs(const Eigen::ArrayXd& re, const Eigen::ArrayXd& im) {
  return std::sqrt((re.square() + im.square()).mean());
}

}  // namespace

PoleWindow band_window(const Eigen::ArrayXd& omega) { return {omega.minCoeff(), omega.maxCoeff()}; }

PoleWindow prior_window(const PriorRanges& priors) {
  const double beta = std::max(std::abs(priors.beta.lo), std::abs(priors.beta.hi));
  return {0.0, std::max(priors.lambda.hi, std::hypot(priors.alpha.hi, beta))};
}

bool plausible(const Order& order, const double* theta, const Eigen::ArrayXd& omega) {
  return plausible(order, theta, omega, band_window(omega));
}

bool plausible(const Order& order, const double* theta, const Eigen::ArrayXd& omega, const PoleWindow& window) {
  const double lo = window.lo, hi = window.hi;
  for (int q = 0; q < order.q(); ++q) {
    const double l = theta[Order::lambda(q)];
    if (!(l >= lo && l <= hi)) return false;
  }
  for (int s = 0; s < order.s(); ++s) {
    const double w0 = std::hypot(theta[order.alpha(s)], theta[order.beta(s)]);
    if (!(w0 >= lo && w0 <= hi)) return false;
  }
  Eigen::ArrayXd re, im;
  evaluate_multipole(order, theta, omega, re, im);
  const Eigen::ArrayXd abs_g = (re.square() + im.square()).sqrt();
  if (!(abs_g.minCoeff() >= kMinAbsG && abs_g.maxCoeff() <= kMaxAbsG)) return false;
  return is_passive(order, theta);
}

Simulation simulate(const Order& order, const Grid& grid, double noise_lo, double noise_hi, const PriorRanges& ranges,
                    std::uint64_t seed, const SimulationFilter& accept, const std::optional<PoleWindow>& window) {
  ADMITGEN_ENSURE(noise_lo > 0.0 && noise_hi >= noise_lo, "noise range [{}, {}]", noise_lo, noise_hi);
  Simulation sim;
  sim.order = order;
  sim.grid = grid;
  sim.data.path = fmt::format("simulated {} on {}", order.name(), grid.name);
  sim.data.f_hz = grid.f_hz();
  const Eigen::ArrayXd omega = sim.data.omega();
  sim.window = window ? *window : band_window(omega);
  Rng rng(seed);
  const PriorTransform prior(order, ranges, false);
  Eigen::VectorXd u(order.dim()), theta(order.dim());
  constexpr long kMaxDraws = 10'000'000;
  do {
    ADMITGEN_ENSURE(sim.prior_draws < kMaxDraws, "no plausible {} among {} prior draws", order.name(), kMaxDraws);
    for (Eigen::Index k = 0; k < u.size(); ++k) u[k] = rng.uniform();
    prior(u.data(), theta.data());
    ++sim.prior_draws;
  } while (!plausible(order, theta.data(), omega, sim.window) || (accept && !accept(theta.data(), omega)));
  fold_to_reduced(order, theta.data());
  sim.theta = theta;
  Eigen::ArrayXd re, im;
  evaluate_multipole(order, theta.data(), omega, re, im);
  sim.noise = noise_lo * std::exp(rng.uniform() * std::log(noise_hi / noise_lo));
  sim.sigma = sim.noise * rms_abs(re, im);
  const double per_component = sim.sigma / std::sqrt(2.0);
  sim.data.y.resize(omega.size());
  for (Eigen::Index i = 0; i < omega.size(); ++i) {
    const double nr = rng.normal(), ni = rng.normal();
    sim.data.y[i] = {re[i] + per_component * nr, im[i] + per_component * ni};
  }
  return sim;
}

Eigen::ArrayXd generative_weights(const Simulation& sim, double noise_lo, double noise_hi, const NestedRun& run) {
  Eigen::ArrayXd w = posterior_weights(run);
  const Eigen::ArrayXd omega = sim.data.omega();
  const MultipoleGrid grid(omega);
  const double half_k = static_cast<double>(real_data_count(DataCount::two_per_point, sim.data.size())) / 2.0;
  Eigen::ArrayXd re, im;
  for (std::size_t i = 0; i < run.size(); ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    if (w[ii] == 0.0) continue;
    const double* th = run.point(i);
    if (!plausible(sim.order, th, omega, sim.window)) {
      w[ii] = 0.0;
      continue;
    }
    grid.evaluate(sim.order, th, re, im);
    const double s = ((sim.data.y.real() - re).square() + (sim.data.y.imag() - im).square()).sum();
    const double r2 = (re.square() + im.square()).mean();
    // σ per component in [c_lo, c_hi]·r/√2 ⇔ S/σ² ∈ [2S/(c_hi² r²), 2S/(c_lo² r²)], S/σ² ~ χ²_K; P(χ²_K ≤ x) = P(K/2, x/2).
    const double p = boost::math::gamma_p(half_k, s / (noise_lo * noise_lo * r2)) -
                     boost::math::gamma_p(half_k, s / (noise_hi * noise_hi * r2));
    w[ii] *= std::max(p, 0.0);
  }
  const double total = w.sum();
  ADMITGEN_ENSURE(total > 0.0, "no posterior mass in the plausible set ({} on {})", sim.order.name(), sim.grid.name);
  return w / total;
}

ReportFamily report_family(Family f) {
  switch (f) {
    case Family::g_inf: return ReportFamily::g_inf;
    case Family::a:
    case Family::lambda: return ReportFamily::real_pole;
    case Family::b:
    case Family::c: return ReportFamily::pair_residue;
    case Family::alpha:
    case Family::beta: return ReportFamily::pair_pole;
  }
  throw InternalError("unhandled Family");
}

std::string family_label(ReportFamily f) {
  switch (f) {
    case ReportFamily::g_inf: return "G_inf";
    case ReportFamily::real_pole: return "A/lambda";
    case ReportFamily::pair_residue: return "B/C";
    case ReportFamily::pair_pole: return "alpha/beta";
  }
  throw InternalError("unhandled ReportFamily");
}

namespace {

std::string sampler_name(SamplerKind k) { return k == SamplerKind::full ? "full" : "poles"; }

/// `count` independent draws of point indices with probabilities `w` (sum 1), by inversion.
std::vector<std::size_t> iid_draws(const Eigen::ArrayXd& w, int count, Rng& rng) {
  std::vector<double> cumulative(static_cast<std::size_t>(w.size()));
  double c = 0.0;
  for (Eigen::Index i = 0; i < w.size(); ++i) cumulative[static_cast<std::size_t>(i)] = (c += w[i]);
  std::vector<std::size_t> idx;
  for (int k = 0; k < count; ++k) {
    const double u = rng.uniform() * c;
    auto it = std::upper_bound(cumulative.begin(), cumulative.end(), u);
    std::size_t i = std::min(static_cast<std::size_t>(it - cumulative.begin()), cumulative.size() - 1);
    while (w[static_cast<Eigen::Index>(i)] == 0.0 && i > 0) --i;  // never a point of zero weight
    idx.push_back(i);
  }
  return idx;
}

SbcReplicate run_replicate(const SbcSettings& settings, int index, SamplerKind kind) {
  const std::uint64_t seed = derive_seed(settings.seed, static_cast<std::uint64_t>(index));
  const auto n_orders = settings.orders.size();
  const Order& order = settings.orders[static_cast<std::size_t>(index) % n_orders];
  const Grid& grid = settings.grids[(static_cast<std::size_t>(index) / n_orders) % settings.grids.size()];
  const PriorRanges priors = band_priors(grid, settings.base_priors);
  // The band prior's R admits every pole of the prior (prior_window); Table 1's clipped prior keeps the band.
  const std::optional<PoleWindow> window =
      priors.residues == ResiduePrior::gaussian ? std::optional<PoleWindow>(prior_window(priors)) : std::nullopt;
  const Simulation sim = simulate(order, grid, settings.noise_lo, settings.noise_hi, priors, seed, {}, window);

  FitSettings fit;
  fit.priors = priors;
  fit.priors_origin = "band priors of " + grid.name;
  fit.sampler.live = settings.live;
  fit.sampler.seed = derive_seed(seed, 1);
  fit.sampler_kind = kind;
  fit.threads = 1;
  const ModelResult model = fit_order(sim.data, order, fit);

  SbcReplicate r;
  r.index = index;
  r.order = order;
  r.grid = grid.name;
  r.noise = sim.noise;
  r.prior_draws = sim.prior_draws;
  r.sampler = sampler_name(kind);
  r.sampler_used = model.sampler;
  r.log_z = model.run.log_z;
  r.max_log_l = model.run.max_log_likelihood;
  r.log_l_truth = Likelihood(sim.data, order, DataCount::two_per_point)(sim.theta.data());
  const Eigen::ArrayXd fit_w = posterior_weights(model.run);
  const Eigen::ArrayXd w = generative_weights(sim, settings.noise_lo, settings.noise_hi, model.run);
  r.ess = effective_sample_size(w);
  double outside = 0.0;
  for (std::size_t i = 0; i < model.run.size(); ++i)
    if (fit_w[static_cast<Eigen::Index>(i)] > 0.0 && !plausible(order, model.run.point(i), sim.data.omega(), sim.window))
      outside += fit_w[static_cast<Eigen::Index>(i)];
  r.outside_mass = outside;

  Rng rng(derive_seed(seed, kind == SamplerKind::full ? 2 : 3));
  const auto draws = iid_draws(w, settings.draws, rng);
  const auto passive = passivity::passive_estimate(sim.data, order,
                                                   best_samples(model, passivity::PassiveEstimate::kCandidates),
                                                   DataCount::two_per_point);
  Eigen::VectorXd pe = passive.theta;
  fold_to_reduced(order, pe.data());
  r.passive_changed = passive.changed;
  const auto names = order.parameter_names();
  const auto families = order.families();
  for (int k = 0; k < order.dim(); ++k) {
    ParameterRank pr;
    pr.name = names[static_cast<std::size_t>(k)];
    pr.family = families[static_cast<std::size_t>(k)];
    pr.truth = sim.theta[k];
    for (std::size_t i : draws) pr.rank += model.run.point(i)[k] < pr.truth ? 1 : 0;
    const ParameterSummary& s = model.parameters[static_cast<std::size_t>(k)];
    pr.mean = s.mean;
    pr.std = s.std;
    pr.passive_z = s.std > 0.0 ? (pe[k] - s.mean) / s.std : 0.0;
    r.ranks.push_back(pr);
  }
  return r;
}

}  // namespace

std::vector<SbcReplicate> run_sbc(const SbcSettings& settings, const std::function<void(const SbcReplicate&)>& done) {
  ADMITGEN_ENSURE(!settings.orders.empty() && !settings.grids.empty() && !settings.samplers.empty(),
                  "empty SBC design");
  ADMITGEN_ENSURE((settings.draws + 1) % 40 == 0, "draws + 1 = {} is not a multiple of 40", settings.draws + 1);
  const std::size_t n_samplers = settings.samplers.size();
  const std::size_t tasks = static_cast<std::size_t>(settings.replicates) * n_samplers;
  std::vector<SbcReplicate> out(tasks);
  std::vector<std::size_t> queue(tasks);
  // Largest orders first (the pool balances better), ties by task index.
  for (std::size_t t = 0; t < tasks; ++t) queue[t] = t;
  const auto dim = [&](std::size_t t) {
    return settings.orders[(t / n_samplers) % settings.orders.size()].dim();
  };
  std::stable_sort(queue.begin(), queue.end(), [&](std::size_t a, std::size_t b) { return dim(a) > dim(b); });
  run_in_parallel(queue, settings.threads, [&](std::size_t t) {
    out[t] = run_replicate(settings, static_cast<int>(t / n_samplers), settings.samplers[t % n_samplers]);
    if (done) done(out[t]);
  });
  return out;
}

bool in_central(int rank, int draws, double level) {
  // rank ∈ {0..L}: the central set is the (L + 1)·level middle values.
  // The tail count is rounded to the nearest integer first: 40 · 0.05 / 2 is 1.0000000000000009 in doubles.
  const double values = static_cast<double>(draws + 1);
  const double tail = std::ceil(values * (1.0 - level) / 2.0 - 1e-9);
  return rank >= tail && rank <= values - 1.0 - tail;
}

Uniformity rank_uniformity(const std::vector<int>& ranks, int draws, int bins) {
  ADMITGEN_ENSURE(bins >= 2 && (draws + 1) % bins == 0, "{} bins over {} rank values", bins, draws + 1);
  Uniformity u;
  u.n = static_cast<int>(ranks.size());
  u.bins = bins;
  u.counts.assign(static_cast<std::size_t>(bins), 0);
  const int width = (draws + 1) / bins;
  for (int r : ranks) ++u.counts[static_cast<std::size_t>(r / width)];
  if (u.n == 0) return u;
  const double expected = static_cast<double>(u.n) / bins;
  for (int c : u.counts) u.chi2 += (c - expected) * (c - expected) / expected;
  u.p_value = boost::math::gamma_q((bins - 1) / 2.0, u.chi2 / 2.0);
  return u;
}

namespace {

double quantile_of(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(i);
  return i + 1 < v.size() ? v[i] * (1.0 - f) + v[i + 1] * f : v[i];
}

}  // namespace

std::vector<FamilySummary> summarize_sbc(const std::vector<SbcReplicate>& replicates, int draws, int bins) {
  std::vector<std::string> samplers;
  for (const auto& r : replicates)
    if (std::find(samplers.begin(), samplers.end(), r.sampler) == samplers.end()) samplers.push_back(r.sampler);
  std::vector<FamilySummary> out;
  for (const auto& sampler : samplers)
    for (ReportFamily fam : {ReportFamily::g_inf, ReportFamily::real_pole, ReportFamily::pair_residue,
                             ReportFamily::pair_pole}) {
      FamilySummary s;
      s.sampler = sampler;
      s.family = fam;
      std::vector<int> pooled;
      std::map<std::string, std::vector<int>> by_name;
      std::vector<double> abs_z;
      int c50 = 0, c95 = 0;
      for (const auto& r : replicates) {
        if (r.sampler != sampler) continue;
        bool any = false;
        for (const auto& p : r.ranks) {
          if (report_family(p.family) != fam) continue;
          any = true;
          pooled.push_back(p.rank);
          by_name[p.name].push_back(p.rank);
          abs_z.push_back(std::abs(p.passive_z));
          c50 += in_central(p.rank, draws, 0.5);
          c95 += in_central(p.rank, draws, 0.95);
        }
        s.replicates += any;
      }
      s.instances = static_cast<int>(pooled.size());
      if (s.instances == 0) continue;
      s.coverage50 = static_cast<double>(c50) / s.instances;
      s.coverage95 = static_cast<double>(c95) / s.instances;
      s.pooled = rank_uniformity(pooled, draws, bins);
      double min_p = 1.0;
      for (const auto& [name, ranks] : by_name) {
        if (static_cast<int>(ranks.size()) < 5 * bins) continue;
        ++s.parameters_tested;
        const double p = rank_uniformity(ranks, draws, bins).p_value;
        if (s.worst_parameter.empty() || p < min_p) {
          min_p = p;
          s.worst_parameter = name;
        }
      }
      s.p_value = s.parameters_tested > 0 ? std::min(1.0, min_p * s.parameters_tested) : 1.0;
      s.passive_abs_z_median = quantile_of(abs_z, 0.5);
      s.passive_abs_z_p90 = quantile_of(abs_z, 0.9);
      out.push_back(s);
    }
  return out;
}

}  // namespace admitgen::validation

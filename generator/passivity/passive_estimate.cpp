// SPDX-License-Identifier: MIT
#include "passivity/passive_estimate.hpp"

#include "core/errors.hpp"
#include "model/multipole.hpp"
#include "model/passivity.hpp"
#include "passivity/passive_residues.hpp"
#include "passivity/pole_refit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace admitgen::passivity {
namespace {

/// A certified candidate beats an uncertified one; then the higher likelihood wins.
bool better(const PassiveEstimate& a, const PassiveEstimate& b) {
  return (a.certified && !b.certified) || (a.certified == b.certified && a.log_likelihood > b.log_likelihood);
}

/// The estimate from the poles of one sample (docs/passivity.md, "Passive estimate"): the sample itself
/// when it is passive, else its residues refitted under Re G ≥ 0.
PassiveEstimate from_sample(const Order& order, const Eigen::VectorXd& sample, int rank, const ResidueTarget& target,
                            const Likelihood& likelihood, bool keep_passive = true) {
  PassiveEstimate e;
  e.candidate_rank = rank;
  const PassivityResult as_is = continuous_passivity(order, sample.data());
  if (as_is.passive && keep_passive) {
    e.theta = sample;
    e.certified = true;
    e.min_re = as_is.min_re;
  } else {
    const PassiveResidues p = passive_residues(order, sample, target);
    e.theta = p.theta;
    e.certified = p.certified;
    e.min_re = p.certificate.min_re;
    e.rounds = p.rounds;
    e.changed = true;
  }
  e.log_likelihood = likelihood(e.theta.data());
  return e;
}

/// The pole search from one candidate (docs/passivity.md, "Searching the poles"), certified for every ω by
/// the constraint generation of passive_residues at the poles found.
PassiveEstimate searched(const Order& order, const PassiveEstimate& start, const ResidueTarget& target,
                         const Likelihood& likelihood) {
  const PoleRefit refit = refit_poles(order, start.theta, target, PassiveEstimate::kMaxSteps);
  if (refit.accepted == 0) return start;  // the start's poles are a local optimum already
  const PassiveResidues p = passive_residues(order, canonical_terms(order, refit.theta), target);
  PassiveEstimate e = start;
  e.theta = p.theta;
  e.certified = p.certified;
  e.min_re = p.certificate.min_re;
  e.rounds = p.rounds;
  e.changed = true;
  e.poles_searched = true;
  e.search_steps = refit.steps;
  e.log_likelihood = likelihood(e.theta.data());
  return e;
}

/// Where the best sample is not passive, in words: G∞ < 0, or the negative bands of Re G against the data
/// band (docs/passivity.md, "What passivity costs").
std::string violation(const Order& order, const Eigen::VectorXd& sample, const Measurement& data) {
  const PassivityResult r = continuous_passivity(order, sample.data());
  if (r.passive) return "the best sample is passive";
  const double lo = data.f_hz.minCoeff(), hi = data.f_hz.maxCoeff();
  bool in_band = false, below = false, above = false;
  for (const auto& b : r.bands) {
    in_band = in_band || (b.lo < hi && b.hi > lo);
    below = below || b.lo < lo;
    above = above || b.hi > hi;
  }
  std::string where = in_band ? "inside the data band" : "only outside the data band";
  if (!in_band && below && above) where += " (below and above it)";
  else if (!in_band && below) where += fmt::format(" (below {:.4g} Hz)", lo);
  else if (!in_band && above) where += fmt::format(" (above {:.4g} Hz)", hi);
  std::string text = fmt::format("the best sample has Re G < 0 {} (down to {:.3g})", where, r.min_re);
  if (sample[Order::g_inf()] < 0.0)
    text += fmt::format(", with G_inf = {:.3g} < 0, so Re G < 0 at high frequencies", sample[Order::g_inf()]);
  return text;
}

/// What the data allow a passive model (docs/passivity.md, "The passive bound"): with the bound, whether the
/// estimate is near it (then the best sample's better fit needs Re G < 0, and the data say why) or a passive
/// model of more terms fits better.
std::string data_clause(const Measurement& data, double estimate_rms, const numerics::PassiveBound* bound) {
  const DataPassivity d = data_passivity(data);
  const std::string data_text =
      d.negative_points > 0
          ? fmt::format("the data themselves are not passive at {} of {} points (Re y down to {:.3g})",
                        d.negative_points, data.size(), d.min_re)
          : fmt::format("the data are passive in band (min Re y = {:.3g})", d.min_re);
  if (bound == nullptr)
    return d.negative_points > 0 ? data_text
                                 : data_text + ", so a better passive model may exist at another order or with "
                                               "poles far from the sampled ones";
  const double b = bound->relative_rms_residual;
  if (!at_passive_bound(estimate_rms, b))
    return fmt::format("{}; a passive admittance of {} terms fits them at {:.3g} % (the passive bound), so a larger "
                       "order may fit better and stay passive",
                       data_text, bound->terms, 100.0 * b);
  const std::string why =
      d.negative_points > 0
          ? std::string("no passive wall can follow them")
          : std::string("so their real and imaginary parts are far from those of a causal passive wall "
                        "(Kramers-Kronig): `admitgen diagnose` with the data alone (no simulation) names the chain effect, if any");
  return fmt::format("{}, but the best passive admittance of any order found fits them at {:.3g} % (the passive "
                     "bound: {} passive terms by non-negative least squares), {}; this estimate is within {:.2f}x of "
                     "that bound",
                     data_text, 100.0 * b, bound->terms, why, estimate_rms / b);
}

std::string cost_reason(const Order& order, const Eigen::VectorXd& best_sample, const Measurement& data,
                        double estimate_rms, const numerics::PassiveBound* bound) {
  return fmt::format("{}; no passive {} with poles near the best samples' fits better (pole search from {} starts); {}",
                     violation(order, best_sample, data), order.name(), PassiveEstimate::kStarts,
                     data_clause(data, estimate_rms, bound));
}

}  // namespace

const numerics::PassiveBound& LazyPassiveBound::get() const {
  std::call_once(computed_,
                 [this] { bound_ = numerics::passive_bound(data_.omega(), data_.y, Eigen::ArrayXd::Ones(data_.size())); });
  return *bound_;
}

PassiveEstimate passive_estimate(const Measurement& data, const Order& order,
                                 const std::vector<Eigen::VectorXd>& candidates, DataCount count, int starts,
                                 const LazyPassiveBound* bound, double admittance_scale) {
  ADMITGEN_ENSURE(!candidates.empty(), "passive estimate of {}: no samples", order.name());
  const Likelihood likelihood(data, order, count);
  const double data_norm2 = data.y.abs2().sum();
  const auto rel_rms = [&](const Eigen::VectorXd& th) {
    return std::sqrt(likelihood.sum_squared_residual(th.data()) / data_norm2);
  };
  // The likelihood weighs every point's complex residual equally: unit weights; the prior's rows weigh each
  // residue by σ/s_k, σ the best sample's RMS residual per real component (the noise the likelihood infers).
  const double sigma = std::sqrt(likelihood.sum_squared_residual(candidates.front().data()) / (2.0 * data.size()));
  const ResidueTarget target{data.omega(), data.y, Eigen::ArrayXd::Ones(data.size()), sigma, admittance_scale};
  std::vector<PassiveEstimate> tried;
  const int n = std::min<int>(PassiveEstimate::kCandidates, static_cast<int>(candidates.size()));
  for (int k = 0; k < n; ++k) {
    tried.push_back(from_sample(order, candidates[static_cast<std::size_t>(k)], k, target, likelihood));
    if (k == 0 && !tried.front().changed) break;  // the best sample itself is passive: nothing can beat it
  }
  std::stable_sort(tried.begin(), tried.end(), better);
  PassiveEstimate best = tried.front();
  best.sampled_poles_relative_rms_residual = rel_rms(best.theta);
  if (best.changed && order.buffers() > 0 && starts > 0) {
    for (int k = 0; k < std::min<int>(starts, static_cast<int>(tried.size())); ++k) {
      const PassiveEstimate e = searched(order, tried[static_cast<std::size_t>(k)], target, likelihood);
      if (better(e, best)) best = e;
    }
    best.sampled_poles_relative_rms_residual = rel_rms(tried.front().theta);
  }
  const auto kappa = [&](const PassiveEstimate& e) { return term_conditioning(order, e.theta, data.omega()); };
  if (kappa(best) > PassiveEstimate::kMaxConditioning && order.buffers() > 0) {
    // Ill-conditioned (docs/passivity.md, "Conditioning"): the MAP residues of the best samples, passive or not,
    // and the pole search from them; the most likely certified one within kMaxConditioning is taken when it fits
    // within kConditioningCost of the estimate's residual, else the trade-off is stated.
    const double rms = rel_rms(best.theta);
    const int samples = std::min(std::max(starts, 1), n);
    std::optional<PassiveEstimate> well;
    for (int k = 0; k < samples; ++k) {
      const PassiveEstimate map =
          from_sample(order, candidates[static_cast<std::size_t>(k)], k, target, likelihood, false);
      for (const PassiveEstimate& e : {map, starts > 0 ? searched(order, map, target, likelihood) : map})
        if (e.certified && kappa(e) <= PassiveEstimate::kMaxConditioning && (!well || better(e, *well))) well = e;
    }
    if (well && rel_rms(well->theta) <= PassiveEstimate::kConditioningCost * rms) {
      best = *well;
      best.sampled_poles_relative_rms_residual = rel_rms(tried.front().theta);
    } else {
      best.conditioning_tradeoff =
          well ? fmt::format("the best certified estimate within conditioning {:g} fits at {:.3g} % ({:.2f}x this one's "
                             "residual, more than {:g}x): emit uses this one",
                             PassiveEstimate::kMaxConditioning, 100.0 * rel_rms(well->theta), rel_rms(well->theta) / rms,
                             PassiveEstimate::kConditioningCost)
               : fmt::format("no certified estimate within conditioning {:g} was found from the {} best samples: emit "
                             "uses this one",
                             PassiveEstimate::kMaxConditioning, samples);
    }
  }
  best.best_sample_log_likelihood = likelihood(candidates.front().data());
  best.best_sample_relative_rms_residual = rel_rms(candidates.front());
  best.relative_rms_residual = rel_rms(best.theta);
  best.conditioning = kappa(best);
  best.best_sample_conditioning = term_conditioning(order, candidates.front(), data.omega());
  if (best.relative_rms_residual > PassiveEstimate::kCostRatio * best.best_sample_relative_rms_residual) {
    const numerics::PassiveBound* b = bound != nullptr ? &bound->get() : nullptr;
    if (b != nullptr) best.passive_bound_relative_rms_residual = b->relative_rms_residual;
    best.cost_reason = cost_reason(order, candidates.front(), data, best.relative_rms_residual, b);
  }
  return best;
}

DataPassivity data_passivity(const Measurement& data) {
  DataPassivity d;
  d.min_re = data.y.real().minCoeff();
  d.negative_points = static_cast<int>((data.y.real() < 0.0).count());
  return d;
}

std::string conditioning_warning(const Order& order, const PassiveEstimate& e) {
  if (!(e.conditioning > PassiveEstimate::kMaxConditioning)) return {};
  return fmt::format("the passive estimate of {} is ill-conditioned: its terms sum to {:.3g}x max |G| in band (the best "
                     "sample: {:.3g}x), so a fixed-point header loses {:.1f} bits to cancellation; {}; emit's fidelity "
                     "check proves whether a q15 header still matches the model, and a smaller order avoids it",
                     order.name(), e.conditioning, e.best_sample_conditioning, std::log2(e.conditioning),
                     e.conditioning_tradeoff.empty() ? "no better-conditioned passive estimate was found"
                                                     : e.conditioning_tradeoff);
}

std::string passivity_cost_warning(const Order& order, const PassiveEstimate& e) {
  if (e.cost_reason.empty()) return {};
  return fmt::format("passivity costs {:.4g} nats in the fit of {}: the passive estimate (what emit uses) fits at "
                     "{:.3g} % relative RMS residual against the best sample's {:.3g} % ({:.2f}x): {}",
                     e.best_sample_log_likelihood - e.log_likelihood, order.name(), 100.0 * e.relative_rms_residual,
                     100.0 * e.best_sample_relative_rms_residual,
                     e.relative_rms_residual / e.best_sample_relative_rms_residual, e.cost_reason);
}

}  // namespace admitgen::passivity

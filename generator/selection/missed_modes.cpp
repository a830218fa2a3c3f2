// SPDX-License-Identifier: MIT
// The missed-mode checks of a fit's runs and what the fit says about them (selection/fit.hpp, missed_modes and its
// texts; docs/method.md, "Model selection").
#include "selection/missed_modes.hpp"

#include "core/errors.hpp"
#include "selection/reduced_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace admitgen {

std::vector<MissedMode> missed_modes(const std::vector<ModelResult>& models, double tolerance) {
  std::vector<MissedMode> missed;
  for (std::size_t big = 0; big < models.size(); ++big) {
    const ModelResult& b = models[big];
    std::size_t worst = models.size();
    for (std::size_t small = 0; small < models.size(); ++small) {
      const ModelResult& m = models[small];
      const bool contained = m.order != b.order && m.order.q() <= b.order.q() && m.order.s() <= b.order.s();
      if (contained && m.run.max_log_likelihood > b.run.max_log_likelihood + tolerance &&
          (worst == models.size() || m.run.max_log_likelihood > models[worst].run.max_log_likelihood))
        worst = small;
    }
    if (worst != models.size())
      missed.push_back({big, worst, models[worst].run.max_log_likelihood, false, b.run.max_log_likelihood, false});
  }
  return missed;
}

namespace {

bool pole_sampled(const ModelResult& m) { return m.sampler == kPoleSamplerName; }

/// Both checks on the pole sampler's marginal (selection/reduced_model.hpp; docs/method.md, "Model
/// selection"), between every pair of orders one of which contains the other: the larger order's peak with
/// its surplus poles dropped against the smaller's, and the smaller's peak completed by the larger's surplus
/// poles against the larger's.
std::vector<MissedMode> marginal_missed_modes(const std::vector<ModelResult>& models, OrderMarginals& marginals,
                                              double tolerance) {
  std::vector<MarginalPeak> peak;
  for (const ModelResult& m : models) peak.push_back(marginals.peak(m));
  std::vector<std::optional<MissedMode>> worst(models.size());
  const auto flag = [&](std::size_t order, std::size_t shown, double log_l, bool larger) {
    if (log_l > peak[order].log_l + tolerance && (!worst[order] || log_l > worst[order]->reference_log_l))
      worst[order] = MissedMode{order, shown, log_l, larger, peak[order].log_l, true};
  };
  for (std::size_t small = 0; small < models.size(); ++small)
    for (std::size_t big = 0; big < models.size(); ++big) {
      const Order &s = models[small].order, &b = models[big].order;
      if (s == b || s.q() > b.q() || s.s() > b.s() || !std::isfinite(peak[small].log_l) ||
          !std::isfinite(peak[big].log_l))
        continue;
      const double* theta_small = models[small].run.point(peak[small].row);
      const double* theta_big = models[big].run.point(peak[big].row);
      flag(small, big, reduced_log_marginal(marginals.of(s), s, b, theta_big), true);
      flag(big, small, completed_log_marginal(marginals.of(b), s, theta_small, b, theta_big), false);
    }
  std::vector<MissedMode> missed;
  for (const auto& m : worst)
    if (m) missed.push_back(*m);
  return missed;
}

}  // namespace

std::vector<MissedMode> missed_modes(const Measurement& data, const FitSettings& settings,
                                     const std::vector<ModelResult>& models, OrderMarginals& marginals,
                                     double tolerance) {
  if (!models.empty() && std::all_of(models.begin(), models.end(), pole_sampled))
    return marginal_missed_modes(models, marginals, tolerance);
  std::vector<MissedMode> missed = missed_modes(models, tolerance);
  if (settings.passive) return missed;
  for (std::size_t small = 0; small < models.size(); ++small) {
    const ModelResult& m = models[small];
    if (std::any_of(missed.begin(), missed.end(), [&](const MissedMode& x) { return x.order == small; })) continue;
    if (m.run.size() == 0) continue;
    // The run's own best with its residues refitted the same way, so that only better poles count.
    const double own = std::max(m.run.max_log_likelihood,
                                reduced_log_likelihood(data, m.order, m.order, m.run.point(max_likelihood_index(m.run)),
                                                       settings.priors, settings.data_count));
    std::optional<MissedMode> worst;
    for (std::size_t big = 0; big < models.size(); ++big) {
      const ModelResult& b = models[big];
      if (b.order == m.order || b.order.q() < m.order.q() || b.order.s() < m.order.s() || b.run.size() == 0) continue;
      const double log_l = reduced_log_likelihood(data, m.order, b.order, b.run.point(max_likelihood_index(b.run)),
                                                  settings.priors, settings.data_count);
      if (log_l > own + tolerance && (!worst || log_l > worst->reference_log_l))
        worst = MissedMode{small, big, log_l, true, m.run.max_log_likelihood, false};
    }
    if (worst) missed.push_back(*worst);
  }
  std::sort(missed.begin(), missed.end(), [](const MissedMode& x, const MissedMode& y) { return x.order < y.order; });
  return missed;
}

namespace {

/// "Q1S3: the peak of ln L(poles) … 1281.9 is below 1284.3 reached by …": what a missed mode shows.
std::string missed_mode_finding(const std::vector<ModelResult>& models, const MissedMode& m) {
  const ModelResult &run = models[m.order], &shown = models[m.contained];
  const std::string reached =
      m.marginal ? (m.larger ? "reached by the peak of the larger order" : "reached by the peak of the nested order")
                 : (m.larger ? "reached by the best model of the larger order" : "of the nested order");
  const std::string how =
      m.marginal ? (m.larger ? " with its surplus poles dropped" : " completed by the larger order's surplus poles")
                 : (m.larger ? " with its surplus terms dropped" : "");
  return fmt::format("{}: {} {:.1f} is below {:.1f} {} {}{}", run.order.name(),
                     m.marginal ? "the peak of ln L(poles) (residues and noise integrated out)" : "best ln L",
                     m.own_log_l, m.reference_log_l, reached, shown.order.name(), how);
}

}  // namespace

bool runs_disagree(const ModelResult& m) { return m.run.log_z_error > RerunCheck::kMaxGapNats; }

bool settled(const ModelResult& run, const MissedMode& m) {
  return run.rerun && run.rerun->agrees() && m.reference_log_l - m.own_log_l <= RerunCheck::kMaxGapNats;
}

std::vector<std::string> missed_mode_notes(const std::vector<ModelResult>& models, const std::vector<MissedMode>& missed) {
  std::vector<std::string> notes;
  for (const MissedMode& m : missed) {
    const ModelResult& run = models[m.order];
    if (!settled(run, m)) continue;
    notes.push_back(fmt::format(
        "{}; runs adding {} live points did not reach it either and left ln Z where it was ({:+.2f} ± {:.2f} "
        "nats): that point lies in a region holding no evidence that more live points find, and ln Z of {} stands",
        missed_mode_finding(models, m), run.rerun->live, run.rerun->log_z_shift, run.rerun->error, run.order.name()));
  }
  return notes;
}

std::vector<std::string> missed_mode_warnings(const std::vector<ModelResult>& models,
                                              const std::vector<MissedMode>& missed) {
  std::vector<std::string> warnings;
  for (const MissedMode& m : missed) {
    const ModelResult& run = models[m.order];
    if (settled(run, m)) continue;
    warnings.push_back(fmt::format("{}; the sampler missed a mode of {}, whose ln Z is underestimated (rerun with "
                                   "more live points, {})",
                                   missed_mode_finding(models, m), run.order.name(), setting("sampler.live")));
  }
  return warnings;
}

std::vector<std::string> runs_disagree_warnings(const std::vector<ModelResult>& models) {
  std::vector<std::string> warnings;
  for (const ModelResult& m : models)
    if (runs_disagree(m))
      warnings.push_back(fmt::format("{}: its independent runs ({} live points in all) disagree, ln Z {:.1f} ± {:.1f}: "
                                     "some found a mode others missed, and ln Z of {} is that uncertain (rerun with "
                                     "more live points, {})",
                                     m.order.name(), m.live, m.run.log_z, m.run.log_z_error, m.order.name(),
                                     setting("sampler.live")));
  return warnings;
}

std::vector<std::string> missed_mode_warnings(const std::vector<ModelResult>& models, double tolerance) {
  return missed_mode_warnings(models, missed_modes(models, tolerance));
}

}  // namespace admitgen

// SPDX-License-Identifier: MIT
#include "diagnosis/explanation.hpp"

#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "inference/evidence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <future>

namespace admitgen::diagnosis {
namespace {


/// The index of the largest evidence (the first on ties).
std::size_t best_of(const std::vector<EffectResult>& results) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < results.size(); ++i)
    if (results[i].log_z > results[best].log_z) best = i;
  return best;
}

bool holds(const std::vector<ExplanationStep>& steps, std::size_t candidate) {
  return std::any_of(steps.begin(), steps.end(),
                     [candidate](const ExplanationStep& s) { return s.candidate == candidate; });
}

/// The candidate indices of `steps`, in step order.
std::vector<std::size_t> member_indices(const std::vector<ExplanationStep>& steps) {
  std::vector<std::size_t> out;
  for (const auto& s : steps) out.push_back(s.candidate);
  return out;
}

/// `members` without its element at `j`.
std::vector<std::size_t> without(std::vector<std::size_t> members, std::size_t j) {
  members.erase(members.begin() + static_cast<std::ptrdiff_t>(j));
  return members;
}

/// The search's state and the inputs every round shares.
struct Search {
  const Eigen::ArrayXd& f_hz;
  const Eigen::ArrayXcd& y_real;
  const Gap& gap_before;
  const std::vector<EffectCandidate>& candidates;
  const std::vector<EffectResult>& singles;
  const IdentificationSettings& settings;
  Progress& progress;
  const EffectLikelihood likelihood;
  double log_z_none = 0.0;
  std::uint64_t next_stream = 0;  ///< the first seed stream no run has used yet
  std::vector<std::size_t> dropped;  ///< candidates the backward step took out (not offered again)
  std::vector<Eigen::ArrayXcd> corrections;  ///< each single effect's ŷ − y_sim at its best point (mimics())

  /// The `count` offered candidates whose single-effect correction is most like candidate k's: the
  /// largest |cos| between ŷ_i − y_sim and ŷ_k − y_sim (real inner product over the points), each at its
  /// single-effect best point. Two effects that correct the gap in the same way are what the data tell
  /// apart least (docs/diagnosis.md, "Mimic swap").
  std::vector<std::size_t> mimics(const std::vector<ExplanationStep>& steps, std::size_t k, std::size_t count) const {
    std::vector<std::pair<double, std::size_t>> alike;
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (offered(steps, i) && likeness(i, k) > 0.0) alike.emplace_back(likeness(i, k), i);
    std::stable_sort(alike.begin(), alike.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<std::size_t> out;
    for (std::size_t j = 0; j < std::min(count, alike.size()); ++j) out.push_back(alike[j].second);
    return out;
  }

  /// |cos| between the single-effect corrections ŷ − y_sim of candidates a and b (real inner product over
  /// the points, each at its single-effect best point); 0 when either has none.
  double likeness(std::size_t a, std::size_t b) const {
    const auto dot = [](const Eigen::ArrayXcd& x, const Eigen::ArrayXcd& y) { return (x.conjugate() * y).real().sum(); };
    const double norm = std::sqrt(dot(corrections[a], corrections[a]) * dot(corrections[b], corrections[b]));
    return norm > 0.0 ? std::abs(dot(corrections[a], corrections[b])) / norm : 0.0;
  }

  /// Whether member j of `members` rides beside a partner: another member corrects the gap alike
  /// (likeness ≥ kPartnerLikeness), so the explanation without j needs that partner to take over its part.
  bool beside_partner(const std::vector<std::size_t>& members, std::size_t j) const {
    for (std::size_t k = 0; k < members.size(); ++k)
      if (k != j && likeness(members[j], members[k]) >= kPartnerLikeness) return true;
    return false;
  }

  /// `count` fresh seed streams, the first returned: every batch takes the next block.
  std::uint64_t take_streams(std::size_t count) {
    const std::uint64_t first = next_stream;
    next_stream += count;
    return first;
  }

  /// Whether candidate i may join the explanation `steps` (not in it, not dropped before).
  bool offered(const std::vector<ExplanationStep>& steps, std::size_t i) const {
    return !holds(steps, i) && std::find(dropped.begin(), dropped.end(), i) == dropped.end();
  }

  /// The joint candidate of each list of candidate indices (combine_effects, members in list order),
  /// sampled from the reference densities of what `now` and the single effects know (reference()).
  std::vector<EffectCandidate> combined(const std::vector<std::vector<std::size_t>>& models, const Explanation& now,
                                        double share_now = kReferenceShareJoint) const {
    std::vector<EffectCandidate> out;
    for (const auto& m : models) {
      std::vector<const EffectCandidate*> with;
      for (const std::size_t i : m) with.push_back(&candidates[i]);
      out.push_back(combine_effects(with));
      out.back().reference = reference(m, now, share_now);
    }
    return out;
  }

  /// One reference density per parameter of the joint model `members` (docs/method.md, "Reference
  /// priors in the combined search"): a member of the explanation `now` from its joint posterior there
  /// with uniform share `share_now` (kReferenceShareJoint where it keeps its role, kReferenceShareSingle in
  /// a swap or a backward step, where it may move far), any other from its single-effect posterior
  /// (kReferenceShareSingle).
  /// Empty (the prior) for a model of at most one parameter, evaluated by quadrature.
  std::vector<ReferenceDensity> reference(const std::vector<std::size_t>& members, const Explanation& now,
                                         double share_now) const {
    std::vector<ReferenceDensity> out;
    for (const std::size_t i : members) {
      const auto at = std::find_if(now.steps.begin(), now.steps.end(),
                                   [i](const ExplanationStep& s) { return s.candidate == i; });
      const std::vector<ReferenceDensity> q =
          at != now.steps.end()
              ? reference_densities(candidates[i].priors,
                                    now.member_parameters(static_cast<std::size_t>(at - now.steps.begin()), candidates),
                                    share_now)
              : reference_densities(candidates[i].priors, singles[i].parameters, kReferenceShareSingle);
      out.insert(out.end(), q.begin(), q.end());
    }
    const bool any = std::any_of(out.begin(), out.end(), [](const ReferenceDensity& q) { return !q.uniform(); });
    if (out.size() < 2 || !any) out.clear();
    return out;
  }

  /// Jointly fitted models of candidate lists, on the next free seed streams.
  std::vector<EffectResult> evaluate(const std::vector<std::vector<std::size_t>>& models, const Explanation& now,
                                     double log_z_floor) {
    if (models.empty()) return {};
    const std::vector<EffectCandidate> tried = combined(models, now);
    return with_gaps(models, tried,
                     evaluate_candidates(tried, likelihood, settings, log_z_floor, take_streams(models.size()), progress));
  }

  /// The explanations without one member each (a backward step) against the whole one, ln Z = log_z_whole.
  /// Only one question matters: does any of them come within the decision margin, ln Z ≥ log_z_whole −
  /// 20 dB? So they are screened like an addition round (evaluate_contenders with the reference 40 dB
  /// below the whole explanation: the margin lies 20 dB above it), and run in full only when their
  /// screened evidence lies within kScreenDeciban of the margin or of the best of them; one far below keeps
  /// its screened estimate, which decides the member decisive all the same. The members left sample from
  /// the whole explanation's posterior with a single effect's uniform share: they may take over the work of
  /// the member taken out.
  /// A model flagged in `in_full` (the explanation without a member that rides beside its partner) is run
  /// in full whatever its screening run found, on the next block of streams after the screening's (that
  /// run kept, unless the screening already made the model a contender with its own full run): its
  /// partner must move far from where the whole explanation put it to take over the member's part, which a
  /// screening run of 25 live points can miss.
  std::vector<EffectResult> evaluate_reduced(const std::vector<std::vector<std::size_t>>& models, const Explanation& now,
                                             double log_z_whole, const std::vector<bool>& in_full) {
    if (models.empty()) return {};
    const std::vector<EffectCandidate> tried = combined(models, now, kReferenceShareSingle);
    const double reference = log_z_whole - 2.0 * kDecisiveDeciban * std::log(10.0) / 10.0;
    // No early stop: held to a leader this close, a screening run of 25 live points can stop before it
    // has found a peak that lies far from where the whole explanation put the remaining members.
    IdentificationSettings screened = settings;
    screened.early_stop_deciban = 0.0;
    const std::uint64_t screen_streams = take_streams(models.size());
    std::vector<std::size_t> again;
    std::vector<EffectCandidate> full;
    for (std::size_t k = 0; k < models.size(); ++k)
      if (in_full[k]) {
        again.push_back(k);
        full.push_back(tried[k]);
      }
    const std::uint64_t full_streams = take_streams(again.size());
    // The full runs do not depend on the screening, so with two or more workers they start beside it on
    // one of them (the screening keeps the others): a long full run no longer runs alone at the end.
    // Every run keeps its seed stream, so the results do not depend on the thread count.
    const std::size_t workers = worker_count(settings.threads, models.size() + again.size());
    std::vector<EffectResult> results, runs;
    if (workers >= 2 && !again.empty()) {
      IdentificationSettings beside = screened;
      beside.threads = static_cast<int>(workers - 1);
      IdentificationSettings one = screened;
      one.threads = 1;
      std::future<std::vector<EffectResult>> running = std::async(std::launch::async, [&] {
        return evaluate_candidates(full, likelihood, one, reference, full_streams, progress);
      });
      results = evaluate_contenders(tried, likelihood, beside, reference, screen_streams, progress);
      runs = running.get();
    } else {
      results = evaluate_contenders(tried, likelihood, screened, reference, screen_streams, progress);
      runs = evaluate_candidates(full, likelihood, screened, reference, full_streams, progress);
    }
    // A model whose screening made it a contender already has its full run (evaluate_contenders).
    for (std::size_t k = 0; k < again.size(); ++k) {
      if (results[again[k]].method != "screened") continue;
      runs[k].seconds += results[again[k]].seconds;
      runs[k].cpu_seconds += results[again[k]].cpu_seconds;
      runs[k].calls += results[again[k]].calls;
      results[again[k]] = std::move(runs[k]);
    }
    return with_gaps(models, tried, std::move(results));
  }

  /// The swaps of a swap pass against the explanation `now`: the question of an addition round (which is
  /// best, and is it decisive against now), so screened like one (evaluate_contenders). The members kept
  /// from `now` sample from its posterior with the uniform share of a single effect: the member swapped in
  /// may take over part of what they explained.
  /// `early_stop` false: no screening run stops early (pair_exchange).
  std::vector<EffectResult> evaluate_swaps(const std::vector<std::vector<std::size_t>>& models, const Explanation& now,
                                           bool early_stop = true) {
    const std::vector<EffectCandidate> tried = combined(models, now, kReferenceShareSingle);
    return with_gaps(models, tried,
                     evaluate_contenders(tried, likelihood, early_stop ? settings : without_early_stop(),
                                         now.joint.log_z, take_streams(models.size()), progress));
  }

  /// The settings with no early stop: held to a leader this close, a screening run of 25 live points can
  /// stop before it has found a peak that lies far from where the explanation put its members.
  IdentificationSettings without_early_stop() const {
    IdentificationSettings out = settings;
    out.early_stop_deciban = 0.0;
    return out;
  }

  /// `results` of the models with their gap fields filled and the last member as their candidate.
  std::vector<EffectResult> with_gaps(const std::vector<std::vector<std::size_t>>& models,
                                      const std::vector<EffectCandidate>& tried, std::vector<EffectResult> results) const {
    for (std::size_t k = 0; k < results.size(); ++k) {
      fill_gap(results[k], tried[k], f_hz, y_real, gap_before);
      results[k].candidate = models[k].back();
    }
    return results;
  }

  /// The steps of the explanation `members` (in that order, fitted jointly as `joint`) restated: member
  /// k carries the Bayes factor and the shrink of the first k + 1 members against the first k. Prefixes
  /// of one member are the single effects; longer proper prefixes are evaluated. `prefix` receives the
  /// explanation without the last member.
  std::vector<ExplanationStep> restate(const std::vector<std::size_t>& members, const EffectResult& joint,
                                       const Explanation& now, EffectResult& prefix) {
    std::vector<std::vector<std::size_t>> longer;
    for (std::size_t k = 2; k < members.size(); ++k)
      longer.emplace_back(members.begin(), members.begin() + static_cast<std::ptrdiff_t>(k));
    const std::vector<EffectResult> evaluated = evaluate(longer, now, log_z_none);
    std::vector<const EffectResult*> prefixes{&singles[members.front()]};
    for (const auto& r : evaluated) prefixes.push_back(&r);
    prefixes.push_back(&joint);
    std::vector<ExplanationStep> out{{members.front(), deciban(prefixes[0]->log_z, log_z_none), prefixes[0]->shrink}};
    for (std::size_t k = 1; k < members.size(); ++k)
      out.push_back({members[k], deciban(prefixes[k]->log_z, prefixes[k - 1]->log_z),
                     prefixes[k - 1]->gap_after.total / prefixes[k]->gap_after.total});
    if (members.size() >= 2) prefix = *prefixes[members.size() - 2];
    return out;
  }
};

/// Of the evaluated explanations `models` (their `results`, recorded as a round of `out`), keeps the best
/// when it is decisive (≥ 20 dB) against `out`, restating its steps and `prefix`. Returns whether it did.
bool keep_best(Search& search, const std::vector<std::vector<std::size_t>>& models,
               const std::vector<EffectResult>& results, Explanation& out, EffectResult& prefix) {
  out.rounds.push_back(results);
  const std::size_t best = best_of(results);
  if (deciban(results[best].log_z, out.joint.log_z) < kDecisiveDeciban) return false;
  out.steps = search.restate(models[best], results[best], out, prefix);
  out.joint = results[best];
  return true;
}

/// Evaluates the explanations `swapped` (each `out` with one member replaced), screened like an addition
/// round, and keeps the best when it is decisive (≥ 20 dB) against `out`, restating its steps and `prefix`.
/// Returns whether one was kept (false also when there is none).
bool keep_best_swap(Search& search, const std::vector<std::vector<std::size_t>>& swapped, Explanation& out,
                    EffectResult& prefix) {
  if (swapped.empty()) return false;
  return keep_best(search, swapped, search.evaluate_swaps(swapped, out), out, prefix);
}

/// The swap step after an addition that leaves the residual structured: every earlier member in turn
/// replaced by every candidate still offered (the others and their order kept, all refitted jointly);
/// the best swap is kept when it is decisive (≥ 20 dB) against the explanation as it stands; the swaps
/// are screened like an addition round (evaluate_contenders), only contenders run in full. The last
/// member is left out of the first pass (its alternatives, given the earlier members, were the addition
/// round itself); once a swap is kept those earlier members have changed, so while the residual stays
/// structured the step repeats over every member, the last included, at most settings.swap_passes
/// passes. `prefix` is the explanation without its last member, restated with each swap.
void swap_round(Search& search, Explanation& out, EffectResult& prefix) {
  const std::size_t n = search.candidates.size();
  for (int pass = 0; pass < search.settings.swap_passes; ++pass) {
    const std::vector<std::size_t> members = member_indices(out.steps);
    const std::size_t swappable = pass == 0 ? members.size() - 1 : members.size();
    std::vector<std::vector<std::size_t>> swapped;
    for (std::size_t j = 0; j < swappable; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        if (!search.offered(out.steps, i)) continue;
        swapped.push_back(members);
        swapped.back()[j] = i;
      }
    if (!keep_best_swap(search, swapped, out, prefix) || out.joint.gap_after.whiteness.white) return;
  }
}

/// The mimic swap after an addition that leaves the residual white: a white residual ends the additions,
/// but an explanation can be white and still far from the truth when a member stands in for the effect it
/// mimics and another member makes up the difference (docs/diagnosis.md, "Mimic swap"). So every earlier
/// member in turn is replaced by its kMimicsPerMember closest mimics (Search::mimics), screened like an
/// addition round; the best swap is kept when it is decisive. The backward step then tests every member
/// of what is kept.
void mimic_swap(Search& search, Explanation& out, EffectResult& prefix) {
  const std::vector<std::size_t> members = member_indices(out.steps);
  std::vector<std::vector<std::size_t>> swapped;
  for (std::size_t j = 0; j + 1 < members.size(); ++j)
    for (const std::size_t i : search.mimics(out.steps, members[j], kMimicsPerMember)) {
      swapped.push_back(members);
      swapped.back()[j] = i;
    }
  keep_best_swap(search, swapped, out, prefix);
}

/// The pair exchange after the additions end with the residual still structured (docs/diagnosis.md,
/// "Pair exchange"): the greedy path can end two members away from the truth (one stands in for a true
/// effect and another makes up the difference), which no single swap reaches. For every pair of members
/// taken out together, the rest is grown back by two greedy additions from the candidates not in the
/// explanation: the kThirdsPerPair best third members by screened evidence, then every fourth beside
/// each. All screening runs go without early stop (Search::without_early_stop). The best regrown
/// explanation is kept when it is decisive (≥ 20 dB) against the explanation as it stands. Returns
/// whether one was kept; needs three members.
bool pair_exchange(Search& search, Explanation& out, EffectResult& prefix) {
  const std::vector<std::size_t> members = member_indices(out.steps);
  if (members.size() < 3) return false;
  const std::size_t n = search.candidates.size();
  // Every candidate not in the explanation, a dropped one included: the exchange may bring it back.
  const auto outside = [&](std::size_t i) { return !holds(out.steps, i); };
  // The members kept when members a and b are taken out, in their order.
  std::vector<std::vector<std::size_t>> bases;
  for (std::size_t a = 0; a < members.size(); ++a)
    for (std::size_t b = a + 1; b < members.size(); ++b) bases.push_back(without(without(members, b), a));
  std::vector<std::vector<std::size_t>> grown;
  std::vector<std::size_t> base_of;
  for (std::size_t k = 0; k < bases.size(); ++k)
    for (std::size_t i = 0; i < n; ++i)
      if (outside(i)) {
        grown.push_back(bases[k]);
        grown.back().push_back(i);
        base_of.push_back(k);
      }
  const std::vector<EffectResult> first = search.evaluate_swaps(grown, out, false);
  out.rounds.push_back(first);
  // Each fourth samples from the screened posterior of its base and third (the members kept there may
  // have moved far from where the explanation put them) and the fourth's single-effect one. A fourth
  // that is a better-ranked third of the same base is left out (that set is already tried).
  std::vector<std::vector<std::size_t>> regrown;
  std::vector<EffectCandidate> tried;
  for (std::size_t k = 0; k < bases.size(); ++k) {
    std::vector<std::size_t> ranked;
    for (std::size_t m = 0; m < grown.size(); ++m)
      if (base_of[m] == k) ranked.push_back(m);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [&](std::size_t a, std::size_t b) { return first[a].log_z > first[b].log_z; });
    ranked.resize(std::min(ranked.size(), kThirdsPerPair));
    std::vector<std::size_t> taken;
    for (const std::size_t m : ranked) {
      taken.push_back(grown[m].back());
      Explanation middle;
      for (const std::size_t i : grown[m]) middle.steps.push_back({i, 0.0, 1.0});
      middle.joint = first[m];
      std::vector<std::vector<std::size_t>> fourths;
      for (std::size_t i = 0; i < n; ++i)
        if (outside(i) && std::find(taken.begin(), taken.end(), i) == taken.end()) {
          fourths.push_back(grown[m]);
          fourths.back().push_back(i);
        }
      const std::vector<EffectCandidate> c = search.combined(fourths, middle, kReferenceShareSingle);
      regrown.insert(regrown.end(), fourths.begin(), fourths.end());
      tried.insert(tried.end(), c.begin(), c.end());
    }
  }
  if (regrown.empty()) return false;
  return keep_best(search, regrown,
                   search.with_gaps(regrown, tried,
                                    evaluate_contenders(tried, search.likelihood, search.without_early_stop(),
                                                        out.joint.log_z, search.take_streams(regrown.size()),
                                                        search.progress)),
                   out, prefix);
}

/// The backward step after round `round`: each member against the explanation without it (a single
/// effect from the single effects, the one without the last member from `prefix`, the others
/// evaluated); the weakest is dropped when the explanation with it is not decisively (≥ 20 dB) better,
/// and the step repeats on what is left.
void backward_step(Search& search, std::size_t round, EffectResult prefix, Explanation& out) {
  while (out.steps.size() >= 2) {
    const std::vector<std::size_t> members = member_indices(out.steps);
    const std::size_t last = members.size() - 1;
    std::vector<EffectResult> reduced(members.size());
    std::vector<std::vector<std::size_t>> to_evaluate;
    std::vector<std::size_t> evaluated_at;
    std::vector<bool> in_full;
    for (std::size_t j = 0; j < members.size(); ++j) {
      const std::vector<std::size_t> rest = without(members, j);
      if (rest.size() == 1) {
        reduced[j] = search.singles[rest.front()];
      } else if (j == last) {
        reduced[j] = prefix;
      } else {
        to_evaluate.push_back(rest);
        evaluated_at.push_back(j);
        in_full.push_back(search.beside_partner(members, j));
      }
    }
    const std::vector<EffectResult> evaluated = search.evaluate_reduced(to_evaluate, out, out.joint.log_z, in_full);
    if (!evaluated.empty()) out.rounds.push_back(evaluated);
    for (std::size_t k = 0; k < evaluated.size(); ++k) reduced[evaluated_at[k]] = evaluated[k];
    const std::size_t weakest = best_of(reduced);  // the member whose removal costs least evidence
    const double bf = deciban(out.joint.log_z, reduced[weakest].log_z);
    if (bf >= kDecisiveDeciban) return;
    out.dropped.push_back({members[weakest], bf, round});
    search.dropped.push_back(members[weakest]);
    const std::vector<std::size_t> rest = without(members, weakest);
    out.steps = search.restate(rest, reduced[weakest], out, prefix);
    out.joint = reduced[weakest];
  }
}

/// The addition rounds from round `round` on (each with its swap or mimic swap and its backward step),
/// until no addition is decisive, the explanation holds kMaxExplanationEffects members or the rounds run
/// out; `round` is left at the next round.
void add_members(Search& search, std::size_t& round, Explanation& out) {
  const std::vector<EffectCandidate>& candidates = search.candidates;
  const std::size_t n = candidates.size();
  const IdentificationSettings& settings = search.settings;
  Progress& progress = search.progress;
  const Eigen::ArrayXd& f_hz = search.f_hz;
  const Eigen::ArrayXcd& y_real = search.y_real;
  const Gap& gap_before = search.gap_before;
  for (; round <= kMaxExplanationRounds && out.steps.size() < kMaxExplanationEffects; ++round) {
    // A white residual leaves no structure in the mean; only the noise shape, which the lag-1 test
    // cannot see, may still be missing.
    const bool white = out.joint.gap_after.whiteness.white;
    std::vector<std::size_t> added;
    std::vector<std::vector<std::size_t>> models;
    for (std::size_t i = 0; i < n; ++i) {
      if (!search.offered(out.steps, i)) continue;
      if (white && candidates[i].stage != EffectStage::noise) continue;
      models.push_back(member_indices(out.steps));
      models.back().push_back(i);
      added.push_back(i);
    }
    if (models.empty()) break;
    const std::vector<EffectCandidate> tried = search.combined(models, out);
    std::vector<EffectResult> results = evaluate_contenders(tried, search.likelihood, settings, out.joint.log_z,
                                                            search.take_streams(models.size()), progress);
    out.rounds.push_back(results);
    const std::size_t best = best_of(results);
    const double bf = deciban(results[best].log_z, out.joint.log_z);
    if (bf < kDecisiveDeciban) break;
    results[best].candidate = added[best];
    fill_gap(results[best], tried[best], f_hz, y_real, gap_before);
    EffectResult prefix = out.joint;
    out.steps.push_back({added[best], bf, out.joint.gap_after.total / results[best].gap_after.total});
    out.joint = results[best];
    if (!out.joint.gap_after.whiteness.white) swap_round(search, out, prefix);
    else mimic_swap(search, out, prefix);
    backward_step(search, round, prefix, out);
  }
}

}  // namespace

std::vector<ParameterSummary> Explanation::member_parameters(std::size_t k,
                                                             const std::vector<EffectCandidate>& candidates) const {
  std::size_t offset = 0;
  for (std::size_t j = 0; j < k; ++j) offset += candidates[steps[j].candidate].priors.size();
  const std::size_t n = candidates[steps[k].candidate].priors.size();
  return {joint.parameters.begin() + static_cast<std::ptrdiff_t>(offset),
          joint.parameters.begin() + static_cast<std::ptrdiff_t>(offset + n)};
}

MemberShares member_shares(const std::vector<EffectCandidate>& candidates, const std::vector<std::size_t>& members,
                                  const std::vector<double>& theta, const Eigen::ArrayXcd& y_real,
                                  const Eigen::ArrayXcd& y_sim) {
  const std::size_t m = members.size();
  ADMITGEN_ENSURE(m <= 16, "{} members are too many to share the gap among", m);
  std::vector<std::size_t> start(m + 1, 0);
  for (std::size_t k = 0; k < m; ++k) start[k + 1] = start[k] + candidates[members[k]].priors.size();
  ADMITGEN_ENSURE(theta.size() == start[m], "{} parameters for members with {}", theta.size(), start[m]);
  const double g0 = (y_real - y_sim).abs2().sum();
  ADMITGEN_ENSURE(g0 > 0.0, "no gap to share");
  // v(S) = G(∅) − G(S) for every subset S (bit k: member k acts), the members at their values in theta.
  std::vector<double> v(std::size_t{1} << m, 0.0);
  for (std::size_t mask = 1; mask < v.size(); ++mask) {
    std::vector<const EffectCandidate*> with;
    std::vector<double> t;
    for (std::size_t k = 0; k < m; ++k) {
      if (!(mask >> k & 1u)) continue;
      with.push_back(&candidates[members[k]]);
      t.insert(t.end(), theta.begin() + static_cast<std::ptrdiff_t>(start[k]),
               theta.begin() + static_cast<std::ptrdiff_t>(start[k + 1]));
    }
    v[mask] = g0 - (y_real - combine_effects(with).predict(t.data()).y).abs2().sum();
  }
  // Shapley weights |S|! (m − |S| − 1)! / m!.
  std::vector<double> weight(m, 1.0);
  for (std::size_t s = 0; s < m; ++s) {
    for (std::size_t i = 1; i <= s; ++i) weight[s] *= static_cast<double>(i);
    for (std::size_t i = 1; i <= m - s - 1; ++i) weight[s] *= static_cast<double>(i);
    for (std::size_t i = 1; i <= m; ++i) weight[s] /= static_cast<double>(i);
  }
  MemberShares out{std::vector<double>(m, 0.0), std::vector<double>(m, 0.0)};
  for (std::size_t k = 0; k < m; ++k) {
    out.alone[k] = v[std::size_t{1} << k] / g0;
    for (std::size_t mask = 0; mask < v.size(); ++mask) {
      if (mask >> k & 1u) continue;
      std::size_t size = 0;
      for (std::size_t b = mask; b; b >>= 1) size += b & 1u;
      out.shapley[k] += weight[size] * (v[mask | std::size_t{1} << k] - v[mask]) / g0;
    }
  }
  return out;
}

Explanation explain(const Eigen::ArrayXd& f_hz, const Eigen::ArrayXcd& y_real, const Eigen::ArrayXcd& y_sim,
                    const Gap& gap_before, const std::vector<EffectCandidate>& candidates,
                    const Identification& identification, const IdentificationSettings& settings, Progress& progress) {
  Explanation out;
  std::vector<EffectResult> singles(candidates.size());
  for (const auto& r : identification.effects) singles[r.candidate] = r;
  const std::size_t n = candidates.size();
  Search search{f_hz, y_real, gap_before, candidates, singles, settings, progress,
                EffectLikelihood(y_real), identification.log_z_none, n, {}, {}};
  const double log_z_none = search.log_z_none;
  if (identification.effects.empty()) return out;
  for (std::size_t i = 0; i < n; ++i) {
    const EffectResult& r = singles[i];
    search.corrections.push_back(r.best.size() == candidates[i].priors.size()
                                     ? Eigen::ArrayXcd(candidates[i].predict(r.best.empty() ? nullptr : r.best.data()).y - y_sim)
                                     : Eigen::ArrayXcd());
  }
  const std::size_t first = best_of(singles);
  if (deciban(singles[first].log_z, log_z_none) < kDecisiveDeciban) return out;
  out.steps.push_back({first, deciban(singles[first].log_z, log_z_none), singles[first].shrink});
  out.joint = singles[first];
  std::size_t round = 1;
  for (int exchange = 0;; ++exchange) {
    add_members(search, round, out);
    if (out.joint.gap_after.whiteness.white || exchange >= settings.pair_exchanges) break;
    EffectResult prefix;
    if (!pair_exchange(search, out, prefix)) break;
    if (!out.joint.gap_after.whiteness.white) swap_round(search, out, prefix);
    backward_step(search, round, prefix, out);
  }
  out.joint.bayes_factor_deciban = deciban(out.joint.log_z, log_z_none);
  if (!out.steps.empty()) out.shares = member_shares(candidates, member_indices(out.steps), out.joint.best, y_real, y_sim);
  return out;
}

}  // namespace admitgen::diagnosis

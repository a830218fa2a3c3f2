// SPDX-License-Identifier: MIT
/// @file
/// Validation sweep (a program, not a test) of `diagnose` beyond single effects (docs/diagnosis.md,
/// "Validation"): every two-effect pair at clear sizes, catalogue parameters off for each layer model
/// and multi-layer SPECs, and out-of-vocabulary gaps (tests/diagnosis/explanation_cases.hpp). Prints one
/// line per case and the figures the criteria are stated in:
///   two effects: both named; combined shrink ≥ half the exact model's;
///   material: right parameter, ratio within 30 % in log (|ln r̂ − ln r| ≤ ln 1.3);
///   out of vocabulary, among the cases no single effect halves (best single shrink < 2): unexplained
///   (also among those the exact model halves, i.e. whose gap is more than noise; oov-gaps prints the
///   exact model's shrink of each case without diagnosing).
///   three effects, catalogue parameter + effect, single effects with a mimic, a mimic beside its partner
///   and four effects (the last two composed by another route, ValidationCase::other_route): named
///   exactly (the explanation is the case's effects and nothing else, residual white;
///   explanation_cases.hpp), and without a passenger (no member outside the case's effects).
/// Usage: bench_validation [two|material|oov|oov-gaps|three|catalogue-effect|mimic|partner|four|all] [--live N] [--threads N] [--stride K]
///   [--from I] [--only TEXT] [--parameters] [--rounds] [--screen-live N] [--truth]
///   (default all, 60 live points, all cores, every case; --stride K runs every K-th case of each set,
///   --from I skips the first I of those, --only TEXT keeps those whose label contains TEXT,
///   --parameters prints every member's parameters, --rounds every joint run of the combined search,
///   --screen-live N the live points of the combined search's screening runs, --truth on a miss the case's own
///   effects fitted jointly, their evidence beside the verdict's).
/// A case costs 0.1-62 s of CPU (docs/diagnosis.md: most of it in cases that run every round, out of
/// vocabulary), the 85 cases together well under an hour of CPU; the compact CTest runs a fixed-seed subset.
#include "explanation_cases.hpp"
#include "core/progress.hpp"
#include "inference/evidence.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <ctime>
#include <cstring>
#include <string>

using namespace admitgen;
using namespace admitgen::test;

namespace {

struct Options {
  std::string set = "all";
  int live = 60;
  int threads = 0;
  std::size_t stride = 1;  ///< run every stride-th case of each set (a quicker, still spread-out sample)
  std::size_t from = 0;    ///< of those, start at this one
  std::string only;        ///< run only the cases whose label contains this text
  bool parameters = false;  ///< print every member's parameters (posterior means), not only material's
  bool rounds = false;      ///< print every joint run of the combined search (why a case went the way it did)
  int screen_live = 0;      ///< live points of the combined search's screening runs (0: the default)
  bool truth = false;       ///< on a miss, also fit the case's own effects jointly and print their evidence
};

template <class Cases>
Cases every(Cases cases, const Options& o) {
  Cases out;
  for (std::size_t i = o.from * o.stride; i < cases.size(); i += o.stride)
    if (cases[i].label.find(o.only) != std::string::npos) out.push_back(cases[i]);
  return out;
}

std::string explanation_text(const diagnosis::Verdict& v, const Options& o) {
  std::string out;
  for (const auto& m : v.explanation) {
    out += (out.empty() ? "" : " + ") + m.effect;
    if (m.effect == "material") out += fmt::format("({}={:.3g})", m.parameters.front().first, m.parameters.front().second);
    else if (o.parameters) {
      std::string p;
      for (const auto& [name, value] : m.parameters) p += fmt::format("{}{}={:.3g}", p.empty() ? "" : ",", name, value);
      if (!p.empty()) out += "(" + p + ")";
    }
  }
  return out.empty() ? "-" : out;
}

diagnosis::Diagnosis run(const ValidationCase& c, const Options& o) {
  auto request = case_request(c, o.live);
  request.settings.threads = o.threads;
  if (o.screen_live > 0) request.settings.screen_live = o.screen_live;
  return diagnosis::run_diagnosis(request);
}

/// Every joint run of the combined search, batch by batch (additions, swaps, restated steps, the models
/// of a backward step), with its Bayes factor against no effect.
void print_rounds(const diagnosis::Diagnosis& d) {
  for (std::size_t r = 0; r < d.explanation.rounds.size(); ++r) {
    std::vector<const diagnosis::EffectResult*> sorted;
    for (const auto& e : d.explanation.rounds[r]) sorted.push_back(&e);
    std::sort(sorted.begin(), sorted.end(), [](const auto* a, const auto* b) { return a->log_z > b->log_z; });
    std::string out;
    for (std::size_t k = 0; k < std::min<std::size_t>(6, sorted.size()); ++k)
      out += fmt::format("{}{} {:.0f} dB ({})", k ? ", " : "", sorted[k]->name,
                         deciban(sorted[k]->log_z, d.identification.log_z_none), sorted[k]->method);
    fmt::print("     batch {}: {}\n", r + 1, out);
  }
}

/// The members the backward step dropped, the main cause of an unexplained verdict, and with --rounds
/// every joint run.
void details(const diagnosis::Diagnosis& d, const Options& o) {
  std::string dropped;
  for (const auto& m : d.verdict.dropped)
    dropped += fmt::format(" {}{} ({:.1f} dB)", m.effect, m.parameter.empty() ? "" : " " + m.parameter, m.bayes_factor_deciban);
  if (!dropped.empty()) fmt::print("     dropped:{}\n", dropped);
  const std::string main_cause = diagnosis::main_cause_text(d.verdict);
  if (!main_cause.empty() && d.verdict.effect == "unexplained") fmt::print("     {}\n", main_cause);
  if (o.rounds) print_rounds(d);
}

/// The case's own effects fitted jointly (full nested sampling from the prior, the search's seed): their
/// Bayes factor against no effect beside the verdict's, and whether they leave the residual white; then
/// four runs with the screening's live points from the prior (on streams of their own), to tell a
/// screening that cannot find the truth's peak from one held off it by its reference densities. A
/// miss where the truth has the larger evidence is the search's; one where it has the smaller is the
/// data's (the vocabulary explains them better another way).
void truth_evidence(const ValidationCase& c, const diagnosis::Diagnosis& d, const Options& o) {
  std::vector<const diagnosis::EffectCandidate*> members;
  for (const auto& t : case_truths(c)) {
    const std::string label = t == "material" ? "material " + c.parameter : t;
    const auto it = std::find_if(d.candidates.begin(), d.candidates.end(),
                                 [&](const diagnosis::EffectCandidate& e) { return e.label() == label; });
    if (it == d.candidates.end()) {
      fmt::print("     truth: {} is not a candidate\n", label);
      return;
    }
    members.push_back(&*it);
  }
  const auto request = case_request(c, o.live);
  Progress silent(false);
  const std::vector<diagnosis::EffectCandidate> joint{diagnosis::combine_effects(members)};
  std::vector<diagnosis::EffectResult> r = diagnosis::evaluate_candidates(
      joint, diagnosis::EffectLikelihood(request.real.y), d.settings, -1e300, 1u << 20, silent);
  diagnosis::fill_gap(r.front(), joint.front(), d.f_hz, request.real.y, d.gap);
  fmt::print("     truth {}: {:.0f} dB, white {}; the verdict's explanation {:.0f} dB\n", joint.front().name,
             deciban(r.front().log_z, d.identification.log_z_none), r.front().gap_after.whiteness.white ? "yes" : "no",
             deciban(d.explanation.joint.log_z, d.identification.log_z_none));
  auto few = d.settings;
  few.sampler.live = few.screen_live;
  for (int s = 0; s < 4; ++s) {
    const auto q = diagnosis::evaluate_candidates(joint, diagnosis::EffectLikelihood(request.real.y), few, -1e300,
                                                  (1u << 20) + 1 + static_cast<unsigned>(s), silent);
    fmt::print("     truth, {} live points from the prior, stream {}: {:.0f} dB\n", few.sampler.live, s,
               deciban(q.front().log_z, d.identification.log_z_none));
  }
}

/// Wall time and the CPU time of all threads of the case (the wall time on an idle machine ≈ CPU / cores).
struct Timing {
  double wall = 0.0, cpu = 0.0;
};

void line(const ValidationCase& c, const diagnosis::Diagnosis& d, const std::string& mark, Timing t, const Options& o) {
  fmt::print("{:<4} {:<78.78} -> {:<12} [{}] shrink {:.2f} explained {:.3f} white {} best single {:.2f}  {:.1f} s, CPU {:.1f} s\n",
             mark, c.label, d.verdict.effect, explanation_text(d.verdict, o), d.verdict.shrink, d.verdict.explained,
             d.verdict.white_after ? "yes" : "no", best_single_shrink(d), t.wall, t.cpu);
  std::fflush(stdout);
}

/// The leading single effects with their Bayes factors against none (why a case went the way it did).
void leading_singles(const diagnosis::Diagnosis& d) {
  std::string out;
  for (std::size_t k = 0; k < std::min<std::size_t>(5, d.identification.effects.size()); ++k) {
    const auto& e = d.identification.effects[k];
    out += fmt::format("{}{} {:.0f} dB (shrink {:.2f})", k ? ", " : "", d.candidates[e.candidate].label(),
                       e.bayes_factor_deciban, e.shrink);
  }
  fmt::print("     leading single effects: {}\n", out);
}

Timing timed(const ValidationCase& c, const Options& o, diagnosis::Diagnosis& d) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu = std::clock();  // the process's CPU time, all threads (POSIX)
  d = run(c, o);
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
          static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC};
}

/// Whether every effect of the case is in the explanation (extra members allowed).
bool all_named(const diagnosis::Verdict& v, const ValidationCase& c) {
  for (const auto& t : case_truths(c))
    if (!explains(v, t, t == "material" ? c.parameter : "")) return false;
  return true;
}

/// A sweep scored by named_exactly (explanation_cases.hpp): one line per case, then the rate named
/// exactly, the rate with every effect named (extra members allowed), the members dropped by the
/// backward step, and the largest wall and CPU time of a case.
void named_sweep(const char* set, const std::vector<ValidationCase>& cases, const Options& o) {
  int exact = 0, all = 0, n = 0, dropped = 0, clean = 0;
  double wall_max = 0.0, cpu_max = 0.0;
  std::map<std::string, int> appearances;
  for (const auto& c : cases) {
    diagnosis::Diagnosis d;
    const Timing t = timed(c, o, d);
    const bool ok = named_exactly(d.verdict, c);
    ++n;
    exact += ok;
    all += all_named(d.verdict, c);
    clean += no_passenger(d.verdict, c);
    dropped += !d.verdict.dropped.empty();
    wall_max = std::max(wall_max, t.wall);
    cpu_max = std::max(cpu_max, t.cpu);
    for (const auto& e : case_truths(c)) ++appearances[e];
    line(c, d, ok ? "ok" : (all_named(d.verdict, c) ? "MISS+" : "MISS"), t, o);
    details(d, o);
    if (!ok) leading_singles(d);
    if (!ok && o.truth) truth_evidence(c, d, o);
  }
  std::string counts;
  for (const auto& [e, k] : appearances) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", e, k);
  fmt::print("{}: named exactly {}/{} = {:.0f} %; every effect named (extras allowed) {}/{}; no passenger {}/{} = {:.0f} %; "
             "cases with a dropped member {}; slowest case {:.1f} s wall, {:.1f} s CPU\n  effects appearing: {}\n",
             set, exact, n, n ? 100.0 * exact / n : 0.0, all, n, clean, n, n ? 100.0 * clean / n : 0.0, dropped, wall_max,
             cpu_max, counts);
}

void two_effects(const Options& o) {
  int both = 0, shrink_ok = 0, exactly = 0, clean = 0, n = 0;
  for (const auto& c : every(two_effect_cases(), o)) {
    diagnosis::Diagnosis d;
    const Timing s = timed(c, o, d);
    const bool named = explains(d.verdict, c.truth) && explains(d.verdict, c.truth_second);
    const double exact = exact_shrink(c, d);
    const bool half = d.verdict.shrink >= 0.5 * exact;
    ++n;
    both += named;
    shrink_ok += named && half;
    line(c, d, named ? (half ? "ok" : "ok~") : "MISS", s, o);
    exactly += named_exactly(d.verdict, c);
    clean += no_passenger(d.verdict, c);
    fmt::print("     exact model shrink {:.2f}; named exactly: {}\n", exact, named_exactly(d.verdict, c) ? "yes" : "no");
    details(d, o);
    if (!named) leading_singles(d);
  }
  fmt::print("two effects: both named {}/{} = {:.0f} %; both named with shrink >= half the exact model's {}/{} = {:.0f} %; "
             "named exactly {}/{} = {:.0f} %; no passenger {}/{} = {:.0f} %\n",
             both, n, n ? 100.0 * both / n : 0.0, shrink_ok, n, n ? 100.0 * shrink_ok / n : 0.0, exactly, n,
             n ? 100.0 * exactly / n : 0.0, clean, n, n ? 100.0 * clean / n : 0.0);
}

void material(const Options& o) {
  int right = 0, n = 0;
  for (const auto& c : every(material_cases(), o)) {
    diagnosis::Diagnosis d;
    const Timing s = timed(c, o, d);
    const double r = material_ratio(d.verdict, c.parameter);
    const bool ok = d.verdict.effect != "unexplained" && r > 0.0 && std::abs(std::log(r / c.ratio)) <= std::log(1.3);
    ++n;
    right += ok;
    line(c, d, ok ? "ok" : "MISS", s, o);
  }
  fmt::print("material: right parameter, ratio within 30 % in log {}/{} = {:.0f} %\n", right, n, n ? 100.0 * right / n : 0.0);
}

/// Out of vocabulary: counted by the criterion when no single effect halves the gap (best single shrink
/// < 2); of those, the ones whose gap is real, i.e. the exact model of the case would halve it (exact
/// shrink ≥ 2; below, most of the gap is noise, which no model can take away).
void out_of_vocabulary(const Options& o) {
  int unexplained = 0, n = 0, real_unexplained = 0, real = 0, all_unexplained = 0, all = 0;
  for (const auto& c : every(out_of_vocabulary_cases(), o)) {
    diagnosis::Diagnosis d;
    const Timing s = timed(c, o, d);
    const bool counted = best_single_shrink(d) < 2.0;
    const double exact = exact_shrink(c, d);
    const bool ok = d.verdict.effect == "unexplained";
    ++all;
    all_unexplained += ok;
    if (counted) {
      ++n;
      unexplained += ok;
      if (exact >= 2.0) {
        ++real;
        real_unexplained += ok;
      }
    }
    line(c, d, counted ? (ok ? "ok" : "MISS") : (ok ? "(ok)" : "(-)"), s, o);
    details(d, o);
    fmt::print("     exact model shrink {:.2f}\n", exact);
  }
  fmt::print("out of vocabulary, no single effect halves the gap: unexplained {}/{} = {:.0f} %; of those with a real gap "
             "(exact model shrink >= 2) {}/{} = {:.0f} %; all cases {}/{}\n",
             unexplained, n, n ? 100.0 * unexplained / n : 0.0, real_unexplained, real,
             real ? 100.0 * real_unexplained / real : 0.0, all_unexplained, all);
}

/// The exact model's shrink of every out-of-vocabulary case, without diagnosing (seconds).
void out_of_vocabulary_gaps(const Options& o) {
  for (const auto& c : every(out_of_vocabulary_cases(), o))
    fmt::print("{:<90.90} exact model shrink {:.2f}\n", c.label, exact_shrink(c));
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--live") && i + 1 < argc) o.live = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) o.threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--from") && i + 1 < argc) o.from = static_cast<std::size_t>(std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--stride") && i + 1 < argc) o.stride = static_cast<std::size_t>(std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) o.only = argv[++i];
    else if (!std::strcmp(argv[i], "--screen-live") && i + 1 < argc) o.screen_live = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--parameters")) o.parameters = true;
    else if (!std::strcmp(argv[i], "--rounds")) o.rounds = true;
    else if (!std::strcmp(argv[i], "--truth")) o.truth = true;
    else o.set = argv[i];
  }
  if (o.set == "two" || o.set == "all") two_effects(o);
  if (o.set == "material" || o.set == "all") material(o);
  if (o.set == "oov" || o.set == "all") out_of_vocabulary(o);
  if (o.set == "oov-gaps") out_of_vocabulary_gaps(o);
  if (o.set == "three" || o.set == "all") named_sweep("three effects", every(three_effect_cases(), o), o);
  if (o.set == "catalogue-effect" || o.set == "all")
    named_sweep("catalogue parameter + effect", every(catalogue_effect_cases(), o), o);
  if (o.set == "mimic" || o.set == "all") named_sweep("single effects with a mimic", every(mimic_cases(), o), o);
  if (o.set == "partner" || o.set == "all")
    named_sweep("mimic beside its partner (other route)", every(partner_cases(), o), o);
  if (o.set == "four" || o.set == "all") named_sweep("four effects (other route)", every(four_effect_cases(), o), o);
  return 0;
}

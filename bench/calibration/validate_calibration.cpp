// SPDX-License-Identifier: MIT
/// @file
/// Validation run (a program, not a test; docs/validation.md, "Calibration" and "Order recovery"):
///  1. simulation-based calibration of the fit (validation/calibration.hpp) with each sampler side by side:
///     per parameter family the χ² uniformity of the ranks, the 50 % and 95 % interval coverage, and the
///     passive estimate's distance from the posterior mean in posterior standard deviations;
///  2. order recovery (validation/order_recovery.hpp): confusion matrices of selected against true order,
///     identifiable and unidentifiable cases apart.
/// Tables on stdout; with --out DIR also CSV files (byte-identical for the same options and seed, whatever
/// --threads is). Progress and wall time on stderr.
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/progress.hpp"
#include "data/csv_writer.hpp"
#include "validation/calibration.hpp"
#include "validation/order_recovery.hpp"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <atomic>
#include <chrono>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

using namespace admitgen;
using namespace admitgen::validation;

namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

std::vector<SamplerKind> parse_samplers(const std::string& text) {
  std::vector<SamplerKind> out;
  for (const auto& item : split(text)) out.push_back(parse_sampler_kind(item));
  return out;
}

std::vector<Order> parse_orders(const std::string& text) {
  std::vector<Order> out;
  for (const auto& item : split(text)) out.push_back(Order::parse(item));
  return out;
}

std::string g(double x) { return fmt::format("{:.17g}", x); }

// ---- SBC ---------------------------------------------------------------------------------------------------

std::string sbc_ranks_csv(const std::vector<SbcReplicate>& reps, int draws) {
  std::string s = "replicate,sampler,sampler_used,order,grid,noise,prior_draws,log_l_truth,max_log_l,ess,outside_mass,parameter,"
                  "family,truth,"
                  "rank,draws,in50,in95,posterior_mean,posterior_std,passive_z\n";
  for (const auto& r : reps)
    for (const auto& p : r.ranks)
      s += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.index, r.sampler,
                       r.sampler_used, r.order.name(), r.grid, g(r.noise), r.prior_draws, g(r.log_l_truth),
                       g(r.max_log_l), g(r.ess), g(r.outside_mass), p.name,
                       family_label(report_family(p.family)), g(p.truth), p.rank, draws,
                       in_central(p.rank, draws, 0.5) ? 1 : 0, in_central(p.rank, draws, 0.95) ? 1 : 0, g(p.mean),
                       g(p.std), g(p.passive_z));
  return s;
}

std::string sbc_summary_csv(const std::vector<FamilySummary>& fams) {
  std::string s = "sampler,family,replicates,instances,coverage50,coverage95,chi2_pooled,p_pooled,p_family,"
                  "worst_parameter,parameters_tested,passive_abs_z_median,passive_abs_z_p90,histogram\n";
  for (const auto& f : fams) {
    std::string hist;
    for (int c : f.pooled.counts) hist += (hist.empty() ? "" : " ") + std::to_string(c);
    s += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", f.sampler, family_label(f.family), f.replicates,
                     f.instances, g(f.coverage50), g(f.coverage95), g(f.pooled.chi2), g(f.pooled.p_value),
                     g(f.p_value), f.worst_parameter, f.parameters_tested, g(f.passive_abs_z_median),
                     g(f.passive_abs_z_p90), hist);
  }
  return s;
}

void print_sbc(const SbcSettings& st, const std::vector<SbcReplicate>& reps, const std::vector<FamilySummary>& fams,
               int bins) {
  std::string orders, grids;
  for (const auto& o : st.orders) orders += (orders.empty() ? "" : ",") + o.name();
  for (const auto& gr : st.grids)
    grids += (grids.empty() ? "" : ", ") + fmt::format("{} ({} pts)", gr.name, gr.points);
  fmt::print("Simulation-based calibration: {} replicates, orders {} in turn, grids {}, noise {:.3g}-{:.3g} of rms|G| "
             "(log-uniform), {} live points, L = {} draws, {} rank bins, seed {}\n",
             st.replicates, orders, grids, st.noise_lo, st.noise_hi, st.live, st.draws, bins, st.seed);
  fmt::print("Acceptance: 95 % coverage in [0.92, 0.98] and family p-value >= 0.01 (Bonferroni over its parameters)\n\n");
  fmt::print("{:<7} {:<11} {:>5} {:>6} {:>7} {:>7} {:>8} {:>9} {:>9} {:<10} {:>8} {:>8}  {}\n", "sampler", "family",
             "reps", "ranks", "cov50", "cov95", "chi2", "p pooled", "p family", "worst", "|z| med", "|z| p90",
             "pooled rank histogram");
  for (const auto& f : fams) {
    std::string hist;
    for (int c : f.pooled.counts) hist += fmt::format("{:>4}", c);
    const bool ok = f.coverage95 >= 0.92 && f.coverage95 <= 0.98 && f.p_value >= 0.01;
    fmt::print("{:<7} {:<11} {:>5} {:>6} {:>7.3f} {:>7.3f} {:>8.2f} {:>9.3g} {:>9.3g} {:<10} {:>8.2f} {:>8.2f} {} {}\n",
               f.sampler, family_label(f.family), f.replicates, f.instances, f.coverage50, f.coverage95, f.pooled.chi2,
               f.pooled.p_value, f.p_value, f.worst_parameter, f.passive_abs_z_median, f.passive_abs_z_p90, hist,
               ok ? "" : " <- not met");
  }
  // Per sampler: fallbacks, mass outside R, ESS.
  std::map<std::string, std::vector<const SbcReplicate*>> by;
  for (const auto& r : reps) by[r.sampler].push_back(&r);
  fmt::print("\n{:<7} {:>10} {:>14} {:>16} {:>12} {:>16}\n", "sampler", "replicates", "ran full", "mass outside R",
             "min ESS", "passive changed");
  for (const auto& [name, list] : by) {
    int fell = 0, changed = 0;
    double outside = 0.0, min_ess = 1e300;
    for (const auto* r : list) {
      fell += r->sampler != "full" && r->sampler_used == "full";
      changed += r->passive_changed;
      outside += r->outside_mass;
      min_ess = std::min(min_ess, r->ess);
    }
    fmt::print("{:<7} {:>10} {:>14} {:>16.4f} {:>12.0f} {:>16}\n", name, list.size(), fell,
               outside / static_cast<double>(list.size()), min_ess, changed);
  }
  fmt::print("(mass outside R: mean posterior mass of the fit outside the plausible set, removed by the exact "
             "reweighting; ran full: the pole sampler was asked for and the full sampler ran, selection/fit.hpp "
             "order_sampler)\n\n");
}

// ---- order recovery ----------------------------------------------------------------------------------------

std::string recovery_cases_csv(const std::vector<RecoveryCase>& cases) {
  std::string s = "case,sampler,truth,noise,selected,identifiable,distance_sigma,rms_sigma,nearest_competitor,"
                  "distance_smaller_sigma,extra_terms,fallbacks\n";
  for (const auto& c : cases)
    s += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", c.index, c.sampler, c.truth.name(), g(c.noise),
                     c.selected.name(), c.identifiable ? 1 : 0, g(c.distance), g(c.rms_sigma), c.nearest.name(),
                     g(c.distance_smaller), c.extra_terms, c.fallbacks);
  return s;
}

/// Every order's evidence per case and sampler: attributes a miss to the selected order's ln Z or the truth's.
std::string recovery_evidence_csv(const std::vector<RecoveryCase>& cases) {
  std::string s = "case,sampler,truth,noise,selected,order,log_z,log_z_error,max_log_l,log_l_truth,run_sampler,live\n";
  for (const auto& c : cases)
    for (const auto& e : c.evidence)
      s += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", c.index, c.sampler, c.truth.name(), g(c.noise),
                       c.selected.name(), e.order.name(), g(e.log_z), g(e.log_z_error), g(e.max_log_l),
                       g(c.log_l_truth), e.sampler, e.live);
  return s;
}

std::string confusion_csv(const std::vector<RecoveryCase>& cases) {
  std::map<std::tuple<std::string, int, std::string, std::string>, int> counts;
  for (const auto& c : cases) ++counts[{c.sampler, c.identifiable ? 1 : 0, c.truth.name(), c.selected.name()}];
  std::string s = "sampler,identifiable,truth,selected,count\n";
  for (const auto& [k, n] : counts)
    s += fmt::format("{},{},{},{},{}\n", std::get<0>(k), std::get<1>(k), std::get<2>(k), std::get<3>(k), n);
  return s;
}

void print_recovery(const RecoverySettings& st, const std::vector<RecoveryCase>& cases) {
  std::string noise;
  for (double n : st.noise) noise += (noise.empty() ? "" : ", ") + fmt::format("{:.3g}", n);
  std::string truths;
  for (const auto& t : st.truths) truths += (truths.empty() ? "" : ",") + t.name();
  fmt::print("Order recovery: truths {}, noise {} of rms|G|, {} data sets per cell, grid {} ({} pts), fitted "
             "Q0-{} x S0-{}, {} live points in {} run(s) per order, rule {}, seed {}, design {}\n",
             truths, noise,
             st.per_cell, st.grid.name, st.grid.points, st.qmax, st.smax, st.live, st.runs, st.rule.spelling(), st.seed,
             st.design == RecoveryDesign::distinct
                 ? fmt::format("distinct (natural frequencies a factor >= {:g} apart, pair quality >= {:g}, every term "
                               ">= {:g} of ||G||)",
                               kDistinctRatio, kMinPairQuality, kMinTermShare)
                 : std::string("prior"));
  fmt::print("Identifiable: D = min over the competitors (orders that cannot represent the truth with no more terms) of "
             "||G_true - G_ml||/sigma >= {:g} (D^2 = gain in max ln L, nats)\n",
             kIdentifiableDistance);
  const auto grid = RecoverySettings::order_range(0, st.qmax, 0, st.smax);
  std::set<std::string> samplers;
  for (const auto& c : cases) samplers.insert(c.sampler);
  for (const auto& sampler : samplers)
    for (int ident : {1, 0}) {
      fmt::print("\n{} sampler, {} cases: rows true order, columns selected order\n{:<6}", sampler,
                 ident ? "identifiable" : "unidentifiable", "");
      for (const auto& o : grid) fmt::print("{:>5}", o.name());
      fmt::print("\n");
      for (const auto& t : st.truths) {
        fmt::print("{:<6}", t.name());
        for (const auto& o : grid) {
          int n = 0;
          for (const auto& c : cases)
            n += c.sampler == sampler && c.identifiable == (ident == 1) && c.truth == t && c.selected == o;
          fmt::print("{:>5}", n ? std::to_string(n) : ".");
        }
        fmt::print("\n");
      }
    }
  fmt::print("\n{:<7} {:>6} {:>13} {:>10} {:>15} {:>9} {:>9} {:>9} {:>9} {:>9}\n", "sampler", "noise", "identifiable",
             "correct", "unidentifiable", "smaller", "correct", "+1 term", ">+1 term", "other");
  for (const auto& sampler : samplers)
    for (double nz : st.noise) {
      int ni = 0, ci = 0, nu = 0, smaller = 0, cu = 0, plus1 = 0, more = 0, other = 0;
      for (const auto& c : cases) {
        if (c.sampler != sampler || c.noise != nz) continue;
        if (c.identifiable) {
          ++ni;
          ci += c.selected == c.truth;
        } else {
          ++nu;
          if (c.selected == c.truth) ++cu;
          else if (c.extra_terms > 1) ++more;
          else if (c.extra_terms == 1) ++plus1;
          else if (c.extra_terms < 0) ++smaller;
          else ++other;
        }
      }
      fmt::print("{:<7} {:>6.3g} {:>13} {:>10} {:>15} {:>9} {:>9} {:>9} {:>9} {:>9}\n", sampler, nz, ni,
                 ni ? fmt::format("{:.1f} %", 100.0 * ci / ni) : "-", nu, smaller, cu, plus1, more, other);
    }
  for (const auto& sampler : samplers) {
    int ni = 0, ci = 0, more = 0, fallbacks = 0;
    for (const auto& c : cases) {
      if (c.sampler != sampler) continue;
      ni += c.identifiable;
      ci += c.identifiable && c.selected == c.truth;
      more += !c.identifiable && c.extra_terms > 1;
      fallbacks += c.fallbacks;
    }
    fmt::print("{}: identifiable {}/{} correct ({:.1f} %; acceptance >= 90 %), unidentifiable cases more than one term "
               "above the truth: {} (acceptance 0); orders that ran the full sampler instead: {}\n",
               sampler, ci, ni, ni ? 100.0 * ci / ni : 0.0, more, fallbacks);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Simulation-based calibration and order recovery of the admitgen fit (docs/validation.md)"};
  SbcSettings sbc;
  RecoverySettings rec;
  std::string samplers = "poles", orders = "Q1S1,Q0S2,Q0S1,Q1S2", rec_samplers = "poles", out_dir;
  std::string truths = "Q0S1,Q0S2,Q0S3,Q1S1,Q1S2,Q1S3,Q2S1,Q2S2,Q2S3", noise = "0.003,0.01,0.03";
  int bins = 10, threads = 0, live = 100;
  std::uint64_t seed = 1;
  app.add_option("--replicates", sbc.replicates, "SBC replicates (0: skip SBC)")->capture_default_str();
  app.add_option("--orders", orders, "SBC true orders, used in turn")->capture_default_str();
  app.add_option("--samplers", samplers, "SBC samplers side by side (full, poles)")->capture_default_str();
  app.add_option("--draws", sbc.draws, "posterior draws L per replicate; L + 1 a multiple of 40")->capture_default_str();
  app.add_option("--bins", bins, "rank histogram bins; must divide L + 1")->capture_default_str();
  app.add_option("--live", live, "live points of every fit")->check(CLI::Range(10, 100000))->capture_default_str();
  app.add_option("--per-cell", rec.per_cell, "order recovery: data sets per true order and noise (0: skip)")
      ->capture_default_str();
  app.add_option("--truths", truths, "order recovery: true orders")->capture_default_str();
  app.add_option("--noise", noise, "order recovery: noise levels (complex std / rms|G|)")->capture_default_str();
  app.add_option("--recovery-samplers", rec_samplers, "order recovery: samplers (full, poles)")->capture_default_str();
  std::string prior = "band";
  app.add_option("--prior", prior, "prior of truths and fits: band (fit's default, Gaussian residues) or table1 (the seed "
                                   "paper's uniform box clipped to the band; run it with --samplers full)")
      ->check(CLI::IsMember({"band", "table1"}))
      ->capture_default_str();
  std::string design = "prior";
  app.add_option("--design", design, "order recovery: true models from the plausible prior, or restricted to "
                                     "distinct terms (validation/order_recovery.hpp; too rare for Q2S3)")
      ->check(CLI::IsMember({"prior", "distinct"}))
      ->capture_default_str();
  std::string select = rec.rule.spelling();
  app.add_option("--select", select, "order recovery: selection rule, as fit's --select")->capture_default_str();
  app.add_option("--runs", rec.runs, "order recovery: independent runs per order, as fit's --runs")
      ->check(CLI::Range(1, 64))->capture_default_str();
  std::string case_list;
  app.add_option("--cases", case_list, "order recovery: only these data sets (indices as in order_cases.csv; the "
                                       "other options must be those of the run that listed them)");
  app.add_option("--qmax", rec.qmax, "order recovery: fitted grid Q0-qmax")->capture_default_str();
  app.add_option("--smax", rec.smax, "order recovery: fitted grid S0-smax")->capture_default_str();
  app.add_option("--seed", seed, "seed of the whole run")->capture_default_str();
  app.add_option("--threads", threads, "worker threads (0: all cores)")->capture_default_str();
  app.add_option("--out", out_dir, "directory for the CSV files");
  CLI11_PARSE(app, argc, argv);
  try {
    if (prior == "table1") sbc.base_priors = rec.base_priors = PriorRanges::table1();
    sbc.samplers = parse_samplers(samplers);
    sbc.orders = parse_orders(orders);
    rec.samplers = parse_samplers(rec_samplers);
    rec.truths = parse_orders(truths);
    rec.design = design == "distinct" ? RecoveryDesign::distinct : RecoveryDesign::prior;
    for (const auto& item : split(case_list)) {
      std::size_t used = 0;
      int index = -1;
      try {
        index = std::stoi(item, &used);
      } catch (const std::exception&) {
      }
      if (index < 0 || used != item.size()) throw InputError(fmt::format("--cases: '{}' is not a data set index", item));
      rec.cases.push_back(index);
    }
    rec.rule = SelectionRule::parse(select);
    rec.noise.clear();
    for (const auto& n : split(noise)) rec.noise.push_back(std::stod(n));
    if ((sbc.draws + 1) % 40 != 0 || bins < 2 || (sbc.draws + 1) % bins != 0)
      throw InputError(fmt::format("--draws {} --bins {}: need (draws + 1) a multiple of 40 and of bins", sbc.draws, bins));
    sbc.live = rec.live = live;
    sbc.seed = rec.seed = seed;
    sbc.threads = rec.threads = threads;
    if (!out_dir.empty()) ensure_writable_directory(out_dir);
    Progress progress(true);
    const auto start = std::chrono::steady_clock::now();
    if (sbc.replicates > 0) {
      std::atomic<int> done{0};
      const auto total = static_cast<std::size_t>(sbc.replicates) * sbc.samplers.size();
      const auto reps = run_sbc(sbc, [&](const SbcReplicate& r) {
        progress.update(fmt::format("SBC {}/{} ({} {} {})", ++done, total, r.order.name(), r.grid, r.sampler));
      });
      progress.finish();
      const auto fams = summarize_sbc(reps, sbc.draws, bins);
      print_sbc(sbc, reps, fams, bins);
      if (!out_dir.empty()) {
        write_file_atomically(out_dir + "/sbc_ranks.csv", sbc_ranks_csv(reps, sbc.draws));
        write_file_atomically(out_dir + "/sbc_summary.csv", sbc_summary_csv(fams));
      }
    }
    if (rec.per_cell > 0) {
      std::atomic<int> done{0};
      const auto total =
          (rec.cases.empty() ? rec.truths.size() * rec.noise.size() * static_cast<std::size_t>(rec.per_cell)
                             : rec.cases.size()) *
          rec.samplers.size();
      const auto cases = run_recovery(rec, [&](const RecoveryCase& c) {
        progress.update(fmt::format("order recovery {}/{} ({} {})", ++done, total, c.truth.name(), c.sampler));
      });
      progress.finish();
      print_recovery(rec, cases);
      if (!out_dir.empty()) {
        write_file_atomically(out_dir + "/order_cases.csv", recovery_cases_csv(cases));
        write_file_atomically(out_dir + "/order_confusion.csv", confusion_csv(cases));
        write_file_atomically(out_dir + "/order_evidence.csv", recovery_evidence_csv(cases));
        // Each data set as `admitgen fit` reads it, to re-run a case with other settings.
        for (const auto& c : cases)
          if (c.sampler == cases.front().sampler)
            write_admittance_csv(fmt::format("{}/order_data_{}.csv", out_dir, c.index), c.data.f_hz, c.data.y,
                                 {{"made by", "validate_calibration order recovery"},
                                  {"case", std::to_string(c.index)},
                                  {"seed", std::to_string(rec.seed)},
                                  {"truth", c.truth.name()},
                                  {"noise", g(c.noise)},
                                  {"design", design}});
      }
    }
    fmt::print(stderr, "wall time {:.1f} s\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  } catch (const InputError& e) {
    fmt::print(stderr, "validate_calibration: {}\n", e.what());
    return 2;
  } catch (const InternalError& e) {  // e.g. a design whose truths the rejection cap cannot draw
    fmt::print(stderr, "validate_calibration: {}\n", e.what());
    return 3;
  }
  return 0;
}

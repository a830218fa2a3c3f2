// SPDX-License-Identifier: MIT
#include "cli/fit_command.hpp"

#include "cli/options.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/progress.hpp"
#include "data/csv_reader.hpp"
#include "inference/evidence.hpp"
#include "library/fit_directory.hpp"
#include "io/priors_file.hpp"
#include "selection/fit_cost.hpp"
#include "selection/fit.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <vector>

namespace admitgen::cli {
namespace {

/// The evidence and cost/accuracy table (docs/cli.md, "fit"): per order ln Z and its error, the Bayes factor
/// against the selected order, the buffers it costs per node, and its passive estimate's accuracy
/// (selection/accuracy_target.hpp: relative RMS residual, max |delta alpha| per one-third-octave band, whether it
/// meets the target) and its conditioning (docs/passivity.md, "Conditioning"). The error of ln Z is sqrt(H/n) of one run: a lower bound of the seed scatter, said below.
void print_summary(const FitResult& fit, const FitSettings& settings) {
  const auto& best = fit.models[fit.selected];
  fmt::print("{:<6} {:>12} {:>8} {:>10} {:>11} {:>9} {:>8} {:>8} {:>9} {:>6} {:>6}\n", "order", "ln Z", settings.runs < 2 ? "±≥err" : "± err", "BF [dB]",
             "calls", "seconds", "buffers", "rel.rms", "band|Δα|", "target", "cond.");
  for (const auto& m : fit.models) {
    const OrderAccuracy a = m.accuracy.value_or(OrderAccuracy{});
    fmt::print("{:<6} {:>12.2f} {:>8.2f} {:>10.1f} {:>11} {:>9.2f} {:>8} {:>8.4f} {:>9.4f} {:>6} {:>6.3g}{}\n", m.order.name(),
               m.run.log_z, m.run.log_z_error, deciban(m.run.log_z, best.run.log_z), m.run.calls, m.seconds,
               m.order.buffers(), a.relative_rms, a.max_band_delta_alpha, a.meets ? "met" : "-", m.passive.conditioning,
               &m == &best ? "  <- selected" : "");
  }
  fmt::print("target: {} (the largest |Δα| of the passive estimate against the data in any one-third-octave band)\n",
             settings.target.describe());
  if (settings.runs < 2)
    fmt::print("±≥err: sqrt(H/n) of one run, a lower bound: the seed scatter of ln Z on real data is 2-15 times larger; "
               "--runs 2 measures it\n");
}

/// Removes the output directories this run created (deepest first, only while empty) unless kept:
/// an input error found after the directory was made leaves nothing behind.
class CreatedDirectories {
 public:
  explicit CreatedDirectories(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    for (fs::path p = fs::absolute(dir, ec); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
      created_.push_back(p);
      if (p == p.parent_path()) break;
    }
  }
  CreatedDirectories(const CreatedDirectories&) = delete;
  CreatedDirectories& operator=(const CreatedDirectories&) = delete;
  ~CreatedDirectories() {
    std::error_code ec;
    if (!keep_)
      for (const auto& p : created_) std::filesystem::remove(p, ec);  // fails (harmlessly) if not empty
  }
  void keep() { keep_ = true; }

 private:
  std::vector<std::filesystem::path> created_;  ///< deepest first
  bool keep_ = false;
};

}  // namespace

void setup_fit_command(CLI::App& app, int& exit_code) {
  auto cmd = std::make_shared<FitCommand>();
  auto* sub = app.add_subcommand("fit", "Bayesian order selection and parameter estimation of a multipole admittance");
  sub->footer(
      "Example:\n  admitgen fit samples/basotect_tuberlin/rect_5cm.csv --columns f,_,_,_,_,re,im,_ "
      "--qmax 2 --smax 2 --out out/rect_5cm\n"
      "Writes OUT/fit.json (schema admitgen.fit/1) and OUT/report.html (self-contained, with figures) and prints\n"
      "the evidence table. Beside fit.json for notebooks: posterior.json (schema admitgen.posterior/1: posterior\n"
      "mean and covariance per order), posterior_QxSy.csv (equally weighted samples of every order) and\n"
      "predictive.csv (the data with the posterior median and 95 % band).");
  sub->add_option("data", cmd->data, "Measured data (CSV or whitespace; see --columns, --quantity)")->required();
  sub->add_option("--out,-o", cmd->out, "Output directory (created if missing)")->required();
  add_fit_options(*sub, cmd->read, cmd->settings);
  sub->add_flag("--quiet,-q", cmd->quiet, "No progress or summary output");
  sub->add_flag("--cost-only", cmd->cost_only,
                "Read the data, print the cost estimate (printed before every fit) and stop: nothing is written");
  sub->callback([cmd, &exit_code] { exit_code = run_fit_command(*cmd); });
}

void add_fit_options(CLI::App& app, ReadOptions& read, FitSettings& s) {
  CLI::App* sub = &app;
  add_data_options(*sub, read);
  sub->add_option("--qmax", s.qmax, "Largest number of real poles Q")->check(CLI::Range(0, Order::kMaxPoles))->capture_default_str();
  sub->add_option("--smax", s.smax, "Largest number of complex pole pairs S")->check(CLI::Range(0, Order::kMaxPoles))->capture_default_str();
  sub->add_option("--live", s.sampler.live, "Live points of nested sampling")->check(CLI::Range(10, 100000))->capture_default_str();
  sub->add_option("--seed", s.sampler.seed, "Random seed (each order derives its own stream)")->capture_default_str();
  sub->add_option("--threads,-j", s.threads, "Worker threads over orders (0 = all cores); results do not depend on it")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  add_parsed_option(*sub, "--select", s.rule, SelectionRule::parse,
                    "Selection rule: target (fewest buffers whose passive estimate meets --target-alpha; simplest:10 when "
                    "none does), simplest:DB (fewest buffers among the orders not below the best by more than DB deciban "
                    "plus two errors), cheapest:DB (the same without the errors) or best (highest evidence)")
      ->default_str(s.rule.spelling());
  auto* prior = sub->add_option_function<std::string>(
      "--prior",
      [&s](const std::string& kind) {
        const double scale = s.priors.admittance_scale;
        s.priors = kind == "table1" ? PriorRanges::table1() : PriorRanges::band_of_the_data(scale);
        s.priors_origin = kind;
      },
      "band (default): Gaussian residues scaled to their poles, pole ranges scaled to the data's band; table1: the "
      "seed paper's uniform box over every parameter (run by the full sampler)")
      ->check(CLI::IsMember({"band", "table1"}))->default_str("band");
  sub->add_option_function<double>(
         "--admittance-scale", [&s](double scale) { s.priors.admittance_scale = scale; },
         "Prior standard deviation of each term's contribution to the normalised admittance (band prior)")
      ->check(CLI::PositiveNumber)->default_str(fmt::format("{}", kDefaultAdmittanceScale));
  sub->add_option_function<std::string>(
         "--priors",
         [&s](const std::string& path) {
           s.priors = io::read_priors_file(path);
           s.priors_origin = path;
         },
         "JSON prior ranges overriding Table 1's, e.g. {\"lambda\": [0, 2e5]} (uniform residues, run by the full "
         "sampler); with \"residues\": \"gaussian\" only pole ranges and \"admittance_scale\" (docs/method.md)")
      ->excludes(prior);
  add_parsed_option(*sub, "--likelihood-k", s.data_count, parse_data_count,
                    "Real data per complex point: 2N (default) or N (the paper's)")
      ->check(CLI::IsMember({"2N", "N"}))->default_str(s.data_count == DataCount::two_per_point ? "2N" : "N");
  sub->add_option("--dlogz", s.sampler.dlogz,
                  "Stop when the live points can change ln Z by less than this (default 0.01 + 0.001 (live - 1))")
      ->check(CLI::Range(1e-6, 10.0));
  sub->add_option("--max-iterations", s.sampler.max_iterations, "Iteration cap per order (safety net)")
      ->check(CLI::Range(1L, 100'000'000L))->capture_default_str();
  sub->add_option("--slices", s.sampler.slices, "Slice moves per replacement (0 = 3 + dim)")->check(CLI::Range(0, 1000))->capture_default_str();
  sub->add_option("--grid-growth", s.grid_growth,
                  "When the selected order lies on the edge of the grid (Q = --qmax or S = --smax), add up to this many "
                  "real poles and as many pairs, one row or column at a time, while the data select them and the "
                  "calls stay within the first round's (0 = the grid as given)")
      ->check(CLI::Range(0, Order::kMaxPoles))->capture_default_str();
  sub->add_option("--missed-mode-retries", s.missed_mode_retries,
                  "Re-run orders whose best likelihood is below a nested order's; each round adds runs that double the "
                  "order's live points, merged with its run")
      ->check(CLI::Range(0, 6))->capture_default_str();
  sub->add_option("--target-alpha", s.target.max_band_delta_alpha,
                  "Accuracy target: the largest |delta alpha| per one-third-octave band of the passive estimate "
                  "against the data; the grid grows only while the selected order misses it, and --select target "
                  "ships the fewest buffers that meet it (docs/method.md, \"Accuracy target\")")
      ->check(CLI::Range(1e-6, 1.0))->capture_default_str();
  sub->add_option("--target-rms", s.target.max_relative_rms,
                  "Also require a relative RMS residual |D - G|/|D| of the passive estimate at most this (0 = off)")
      ->check(CLI::Range(0.0, 10.0))->capture_default_str();
  sub->add_option("--max-buffers", s.max_buffers,
                  "Most state buffers (Q + 2S) per node an engine can afford: larger orders are neither grown nor "
                  "selected (0 = no limit)")
      ->check(CLI::Range(0, 3 * Order::kMaxPoles))->capture_default_str();
  sub->add_option("--runs", s.runs,
                  "Independent runs per order, sharing --live and merged; with 2 or more the error of ln Z includes "
                  "their scatter (1 = one run, whose error is sqrt(H/live) alone)")
      ->check(CLI::Range(1, 64))->capture_default_str();
  add_clearing_flag(*sub, "--no-symmetry-reduction", s.reduce_symmetry,
                    "Sample the full prior (both beta signs, all pole orderings); same evidence, slower");
  sub->add_flag("--passive", s.passive,
                "Sample only passive models (Re G >= 0 at every frequency): evidence and posterior under the prior "
                "truncated to passive models");
  add_parsed_option(*sub, "--sampler", s.sampler_kind, parse_sampler_kind,
                    "poles (default): sample the poles, integrate residues and noise exactly (band prior); full: "
                    "sample every parameter (what --prior table1, --priors and --passive run)")
      ->check(CLI::IsMember({"poles", "full"}))->default_str(s.sampler_kind == SamplerKind::full ? "full" : "poles");
}

int run_fit_command(const FitCommand& o) {
  const ReadOptions& read = o.read;
  const FitSettings& settings = o.settings;
  const Measurement data = read_measurement(o.data, read);
  if (o.cost_only || !o.quiet) fmt::print(stderr, "{}\n", spelled(estimate_fit_cost(data, settings).describe()));
  if (o.cost_only) return 0;
  CreatedDirectories created(o.out);
  ensure_writable_directory(o.out);
  Progress progress(!o.quiet);
  progress.message(fmt::format("fitting {} points {:.6g}-{:.6g} Hz over Q0-{} x S0-{}", data.size(), data.f_hz[0],
                               data.f_hz[data.size() - 1], settings.qmax, settings.smax));
  const FitResult fit = run_fit(data, settings, progress);
  if (!o.quiet)
    for (const auto& step : fit.grid.steps) fmt::print(stderr, "grid grown: {}\n", spelled(step));
  const std::string path = (std::filesystem::path(o.out) / "fit.json").string();
  const FitRecord record = library::write_fit_directory(o.out, data, read, settings, fit);
  created.keep();
  if (!o.quiet) {
    print_summary(fit, settings);
    for (const auto& w : *record.warnings) fmt::print(stderr, "warning: {}\n", spelled(w));
    if (record.notes)
      for (const auto& n : *record.notes) fmt::print(stderr, "note: {}\n", spelled(n));
    const auto& chosen = fit.models[fit.selected];
    fmt::print("selected {} ({}); wrote {}\n", chosen.order.name(), settings.rule.describe(), path);
    fmt::print("passive estimate of {} (what emit uses): relative RMS residual {:.3g} % (best sample {:.3g} %), {}\n",
               chosen.order.name(), 100.0 * chosen.passive.relative_rms_residual,
               100.0 * chosen.passive.best_sample_relative_rms_residual,
               !chosen.passive.certified     ? "NOT certified passive"
               : chosen.passive.poles_searched ? "poles and residues refitted under Re G >= 0, certified passive"
               : chosen.passive.changed        ? "residues refitted under Re G >= 0, certified passive"
                                               : "the best sample itself, certified passive");
  }
  return 0;
}

}  // namespace admitgen::cli

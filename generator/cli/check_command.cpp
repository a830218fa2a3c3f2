// SPDX-License-Identifier: MIT
#include "cli/check_command.hpp"

#include "checks/check_suite.hpp"
#include "cli/options.hpp"
#include "io/check_input.hpp"
#include "io/check_report.hpp"

#include <fmt/core.h>

namespace admitgen::cli {

void setup_check_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<CheckOptions>();
  auto* sub = app.add_subcommand("check", "Prove an emitted header (or a fit's model) stable, passive and overflow-free");
  sub->footer(
      "Example:\n  admitgen check wall.h --json\n"
      "Checks: causality, discrete_stability, passivity_continuous, passivity_discrete (Hamiltonian eigenvalue\n"
      "tests), headroom, limit_cycle, fidelity, header_integrity. Exit 0 all hold, 1 a check failed, 2 unusable input.");
  sub->add_option("file", opt->file, "Header written by admitgen emit, or fit.json written by admitgen fit")->required();
  sub->add_flag("--json", opt->json, "Print the report as JSON (schema admitgen.check/1)");
  sub->add_option("--order", opt->order, "fit.json only: check this order (e.g. Q0S2) instead of the selected one");
  sub->add_option("--estimate", opt->estimate,
                  "fit.json only: the parameters checked (passive estimate, posterior mean or max_likelihood sample)")
      ->check(CLI::IsMember({"passive", "mean", "max_likelihood"}))->capture_default_str();
  sub->add_option("--fidelity-tolerance", opt->fidelity_tolerance,
                  "Headers only: largest max |H - G|/|G| in the data band of the filter as the kernel runs it against "
                  "the header's continuous model (docs/checks.md, fidelity)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->callback([opt, &exit_code] { exit_code = run_check_command(*opt); });
}

int run_check_command(const CheckOptions& o) {
  auto subject = io::load_check_subject(o.file, o.order, parse_estimate(o.estimate));
  subject.fidelity_tolerance = o.fidelity_tolerance;
  if (!subject.note.empty()) fmt::print(stderr, "note: {}\n", spelled(subject.note));
  const auto report = checks::run_checks(subject);
  if (o.json)
    fmt::print("{}", io::check_report_json(report));
  else
    fmt::print("{}", io::check_report_text(report));
  return report.passed() ? 0 : 1;
}

}  // namespace admitgen::cli

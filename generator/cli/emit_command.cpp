// SPDX-License-Identifier: MIT
#include "cli/emit_command.hpp"

#include "cli/options.hpp"
#include "codegen/emission.hpp"
#include "codegen/template_text.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "emit/emit.hpp"
#include "io/bands_file.hpp"
#include "io/fit_file.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace admitgen::cli {
namespace {

/// The output file's stem as a C identifier: "out/wall-48k.h" → "wall_48k".
std::string default_name(const std::string& out) {
  std::string s = std::filesystem::path(out).stem().string();
  for (auto& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "admitgen_" + s;
  return s;
}

}  // namespace

void setup_emit_command(CLI::App& app, int& exit_code) {
  auto cmd = std::make_shared<EmitCommand>();
  auto* sub = app.add_subcommand("emit", "Generate the causal C header (recursive convolution) of a fit for the C99 runtime");
  sub->footer(
      "Example:\n  admitgen emit out/fit.json --fs 48000 --fs 96000 --format q31 --name wall --out wall.h\n"
      "The header holds one model per rate (exact poles, numerators refitted at the data frequencies for that\n"
      "rate), the band absorption tables, and a machine-readable block for admitgen check.");
  sub->add_option("fit", cmd->fit, "fit.json written by admitgen fit")->required()->check(CLI::ExistingFile);
  add_emit_options(*sub, cmd->settings);
  sub->add_option("--out,-o", cmd->out, "Header to write")->required();
  sub->add_option("--bands-json", cmd->bands_json, "Also write the band absorption (octave, 1/3 octave) as JSON");
  sub->add_option("--golden", cmd->golden, "Also write bit-exact golden vectors of the first rate (q31/q15)");
  sub->add_option("--golden-seed", cmd->golden_seed, "Seed of the golden vectors' noise segment")->capture_default_str();
  sub->add_option("--templates", cmd->templates, "Directory holding admitgen_boundary.h.in (default: the template built into admitgen)");
  sub->add_flag("--quiet,-q", cmd->quiet, "No summary output");
  sub->add_flag("--allow-unsafe", cmd->allow_unsafe,
                "Write the header even when it fails admitgen check (non-causal, unstable, non-passive, overflow, "
                "limit cycle); each failure is printed as a warning");
  sub->callback([cmd, &exit_code] { exit_code = run_emit_command(*cmd); });
}

void add_emit_options(CLI::App& app, codegen::EmitSettings& s) {
  CLI::App* sub = &app;
  sub->add_option("--fs", s.fs_hz, "Sample rate in Hz (repeatable; whole Hz)")->required();
  add_parsed_option(*sub, "--format", s.format, codegen::parse_format, "Coefficient and data format")
      ->required()->check(CLI::IsMember({"f32", "q31", "q15"}));
  sub->add_option("--name", s.name, "C identifier prefix of the emitted tables (default: output file stem)");
  sub->add_option("--order", s.order, "Emit this order of the fit (e.g. Q0S2) instead of the selected one");
  add_parsed_option(*sub, "--estimate", s.estimate, parse_estimate,
                    "Parameters to emit: passive (best sample's poles, residues refitted under Re G >= 0; certified), "
                    "posterior mean, or max_likelihood sample. A non-passive choice is made passive by the minimal "
                    "change of its residues, stated in the header")
      ->check(CLI::IsMember({"passive", "mean", "max_likelihood"}))->default_str(estimate_name(s.estimate));
  sub->add_option("--fidelity-tolerance", s.fidelity_tolerance,
                  "Largest max |H - G|/|G| in the data band of the emitted filter, as the kernel runs it, against the "
                  "continuous model; a header beyond it is refused (docs/checks.md, fidelity)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  sub->add_option("--fir-taps", s.fir_taps, "FIR taps of the refit (0 = fewest reaching 1e-5 relative error)")
      ->check(CLI::Range(0, 8))->capture_default_str();
  add_clearing_flag(*sub, "--no-passivity-enforcement", s.enforce_passivity,
                    "Experts: emit the chosen estimate as fitted, with a plain least-squares refit (no passivity "
                    "enforcement); a non-passive result is then refused unless --allow-unsafe is given too");
}

int run_emit_command(const EmitCommand& o) {
  codegen::EmitSettings s = o.settings;
  if (s.name.empty()) s.name = default_name(o.out);
  if (!o.golden.empty() && s.format == codegen::Format::f32)
    throw InputError("--golden needs --format q31 or q15 (f32 output is not bit-exact across compilers)");
  const std::string tpl = codegen::load_template(o.templates, "admitgen_boundary.h.in");
  // Everything is computed and checked before anything is written; each file appears whole or not at all.
  const emit::EmitResult result =
      emit::emit(io::read_fit_file(o.fit), o.fit, s, tpl, std::filesystem::path(o.out).filename().string());
  const auto& emission = result.emission;
  const std::string& header = result.header;
  if (!result.safe()) {
    const std::string refusal = spelled(result.refusal(o.out)) + "\n(--allow-unsafe writes it anyway, for experts)";
    if (!o.allow_unsafe) {
      fmt::print(stderr, "admitgen: {}\n", refusal);
      return 1;  // a check found a violation (exit code 1, docs/cli.md); nothing was written
    }
    fmt::print(stderr, "warning: --allow-unsafe: {}\n", refusal);
  }
  const std::string bands = o.bands_json.empty() ? "" : io::bands_text(emission);
  const std::string golden = o.golden.empty() ? "" : codegen::golden_vectors(emission, o.golden_seed);
  write_file_atomically(o.out, header);
  if (!o.bands_json.empty()) write_file_atomically(o.bands_json, bands);
  if (!o.golden.empty()) write_file_atomically(o.golden, golden);
  if (!o.quiet) {
    for (const auto& r : emission.rates)
      fmt::print("{} Hz: {} FIR taps, {} real, {} pairs; refit max rel. error {:.2e} (plain PLRC {:.2e}){}{}\n", r.fs_hz,
                 r.model.fir.size(), r.model.real.size(), r.model.pair.size(), r.model.refit_max_rel_error,
                 r.model.plrc_max_rel_error, r.model.folded.empty() ? "" : "; folded " + std::to_string(r.model.folded.size()),
                 r.model.passive_rounds == 0 ? "" : fmt::format("; refit constrained to Re H >= 0 ({} rounds)", r.model.passive_rounds));
    for (const auto& n : emission.notes) fmt::print("note: {}\n", spelled(n));
    fmt::print("wrote {} ({} {}, {}, {} estimate{})\n", o.out, emission.surface.order.name(), codegen::format_name(s.format), s.name,
               estimate_name(emission.estimate), result.safe() ? "; passes admitgen check" : "; UNSAFE");
  }
  return 0;
}

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
#include "cli/synth_command.hpp"

#include "cli/options.hpp"
#include "data/csv_writer.hpp"
#include "data/read_options.hpp"
#include "io/fit_file.hpp"
#include "physics/material_spec.hpp"
#include "physics/synthetic_measurement.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cstdio>

namespace admitgen::cli {
namespace {

std::string describe_effects(const std::vector<Effect>& effects) {
  if (effects.empty()) return "none";
  std::vector<std::string> names;
  for (const auto& e : effects) names.push_back(to_string(e));
  return fmt::format("{}", fmt::join(names, " "));
}

std::string describe_tube(const TubeSetup& t) {
  const auto length = [](const std::optional<double>& v) { return v ? fmt::format("{} m", *v) : std::string("-"); };
  return fmt::format("diameter {}, mic spacing {}, mic distance {}, temperature {} C", length(t.diameter_m),
                     length(t.spacing_m), length(t.mic1_distance_m), t.temperature_c);
}

CsvProvenance provenance(const SynthCommand& o, const SynthesisRequest& r, const Band& band) {
  return {{"material", o.material},
          {"effects", describe_effects(r.effects)},
          {"noise", r.noise_std > 0.0 ? fmt::format("complex Gaussian, std {} (E|n|^2 = std^2)", r.noise_std)
                                      : std::string("none")},
          {"seed", fmt::format("{}", r.seed)},
          {"frequencies", fmt::format("{} log-spaced points {}-{} Hz", r.f_hz.size(), band.lo_hz, band.hi_hz)},
          {"tube", describe_tube(r.tube)}};
}

}  // namespace

void setup_synth_command(CLI::App& app, int& exit_code) {
  auto cmd = std::make_shared<SynthCommand>();
  auto* sub = app.add_subcommand("synth", "Synthetic measured admittance from physical materials and measurement effects");
  sub->footer(
      "Examples:\n"
      "  admitgen synth --material 'miki(sigma=10000, d=50mm)' --noise 0.01 --out miki.csv\n"
      "  admitgen synth --material 'mpp(hole=0.4mm,t=0.4mm,p=1%) + air(d=50mm)' --effect tube_losses \\\n"
      "      --tube-diameter 0.1 --mic-spacing 0.05 --mic-distance 0.1 --out mpp.csv\n"
      "Layers: delany_bazley(sigma,d) miki(sigma,d) jca(phi,sigma,alpha_inf,lambda,lambda_th,d)\n"
      "        horoshenkov(phi,pore,sigma_s,d) mpp(hole,t,p) air(d), joined front to back by '+';\n"
      "        or multipole(G_inf=..,A_1=..,..) or fit(file=FIT.json[,order=QxSy][,estimate=mean|max_likelihood]).\n"
      "Effects: none reference_plane:delta_m mic_spacing:delta_m mic_mismatch:gain,phase_deg temperature:delta_k\n"
      "         tube_losses edge_gap:width_m,depth_m frame_resonance:f0_hz,q,y_peak\n"
      "         fractional_order:c_plus,c_minus,f_ref_hz air_gap:gap_m heteroscedastic_noise:scale");
  sub->add_option("--material,-m", cmd->material, "Material SPEC, e.g. 'miki(sigma=10000, d=50mm) + air(d=20mm)'")->required();
  sub->add_option("--out,-o", cmd->out, "Output CSV (columns f_hz, re_y, im_y; read by fit without options)")->required();
  sub->add_option("--effect,-e", cmd->effects, "Effect NAME or NAME:k=v,... (repeatable; see below)");
  sub->add_option("--noise", cmd->request.noise_std, "Std of complex Gaussian noise on y (E|n|^2 = std^2)")->capture_default_str();
  sub->add_option("--seed", cmd->request.seed, "Random seed of the noise")->capture_default_str();
  sub->add_option("--band", cmd->band, "Frequency range FMIN:FMAX in Hz")->capture_default_str();
  sub->add_option("--points", cmd->points, "Number of log-spaced frequencies")->check(CLI::Range(2, 1'000'000))->capture_default_str();
  add_tube_options(*sub, cmd->request.tube);
  sub->add_flag("--quiet,-q", cmd->quiet, "No summary output");
  sub->callback([cmd, &exit_code] { exit_code = run_synth_command(*cmd); });
}

int run_synth_command(const SynthCommand& o) {
  const Band band = Band::parse(o.band);
  SynthesisRequest request = o.request;
  request.material = parse_material_spec(o.material, io::read_fit_file);
  request.f_hz = log_spaced_frequencies(band.lo_hz, band.hi_hz, o.points);
  for (const auto& text : o.effects) request.effects.push_back(parse_effect(text));
  const Synthesis result = synthesize(request);
  write_admittance_csv(o.out, request.f_hz, result.y, provenance(o, request, band));
  if (!o.quiet) {
    for (const auto& w : result.warnings) fmt::print(stderr, "warning: {}\n", spelled(w));
    fmt::print("wrote {} points {}-{} Hz to {}\n", request.f_hz.size(), band.lo_hz, band.hi_hz, o.out);
  }
  return 0;
}

}  // namespace admitgen::cli

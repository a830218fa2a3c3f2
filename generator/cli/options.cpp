// SPDX-License-Identifier: MIT
#include "cli/options.hpp"

#include "core/errors.hpp"

#include <map>

namespace admitgen::cli {

CLI::Option* add_clearing_flag(CLI::App& app, const std::string& name, bool& field, const std::string& help) {
  return app.add_flag_callback(name, [&field] { field = false; }, help);
}

DataOptions add_data_options(CLI::App& app, ReadOptions& r, const DataOptionScope& scope) {
  const auto name = [&scope](const char* option) { return "--" + scope.prefix + option; };
  DataOptions added;
  // Each option with the ReadOptions field it sets (DataOptions::take_given copies that field).
  const auto bind = [&added](CLI::Option* option, DataOptions::Take take) {
    added.bound_.push_back({option, take});
    return option;
  };
  bind(add_parsed_option(
           app, name("columns"), r.columns, ColumnMap::parse,
           "What each column holds, by position (f, re, im, mag, phase, _ to skip; e.g. f,_,_,_,_,re,im,_) or by "
           "header name (e.g. \"f=Frequency [Hz],re=Re(Z/Z0),im=Im(Z/Z0)\"); default: from the header's names, "
           "else f,re,im"),
       [](const ReadOptions& f, ReadOptions& t) { t.columns = f.columns; });
  bind(add_parsed_option(app, name("quantity"), r.quantity, parse_quantity,
                         "What the values are (default: from the header's names, else admittance)")
           ->check(CLI::IsMember({"admittance", "impedance", "reflection"})),
       [](const ReadOptions& f, ReadOptions& t) { t.quantity = f.quantity; });
  // Normalised is what an empty rho_c means: the flag only states it (and excludes --rho-c).
  const DataOptions::Take take_rho_c = [](const ReadOptions& f, ReadOptions& t) { t.rho_c = f.rho_c; };
  auto* norm = bind(app.add_flag(name("normalized") + "," + name("normalised"), "Values are normalised by rho0*c0 (default)"),
                    take_rho_c);
  bind(app.add_option(name("rho-c"), r.rho_c, "Values are SI; divide out this rho0*c0 [Pa s/m] (e.g. 413.3)")->excludes(norm),
       take_rho_c);
  bind(add_parsed_option(app, name("band"), r.band, Band::parse, "Keep only FMIN:FMAX [Hz]"),
       [](const ReadOptions& f, ReadOptions& t) { t.band = f.band; });
  // An empty delimiter or decimal separator is sniffed from the file ("auto").
  bind(app.add_option_function<std::string>(
              name("delimiter"),
              [&r](const std::string& t) {
                if (t != "auto") r.format.delimiter = t == "tab" ? '\t' : t == "space" ? ' ' : t[0];
              },
              "Field separator: auto (sniffed), ',', ';', tab or space (runs of blanks)")
           ->check(CLI::IsMember({"auto", ",", ";", "tab", "space"}))
           ->default_str("auto"),
       [](const ReadOptions& f, ReadOptions& t) { t.format.delimiter = f.format.delimiter; });
  bind(app.add_option_function<std::string>(
              name("decimal"), [&r](const std::string& t) { if (t != "auto") r.format.decimal = t[0]; },
              "Decimal separator: auto (sniffed), '.' or ','")
           ->check(CLI::IsMember({"auto", ".", ","}))
           ->default_str("auto"),
       [](const ReadOptions& f, ReadOptions& t) { t.format.decimal = f.format.decimal; });
  bind(app.add_option(name("skip-rows"), r.format.skip_rows, "Lines to skip before reading (preamble lines are also detected)")
           ->check(CLI::NonNegativeNumber)
           ->capture_default_str(),
       [](const ReadOptions& f, ReadOptions& t) { t.format.skip_rows = f.format.skip_rows; });
  bind(add_parsed_option(app, name("magnitude"), r.magnitude, parse_magnitude_scale,
                         "Scale of a mag column: linear or db (20 log10); default from the unit, else linear")
           ->check(CLI::IsMember({"linear", "db"})),
       [](const ReadOptions& f, ReadOptions& t) { t.magnitude = f.magnitude; });
  bind(add_parsed_option(app, name("phase-unit"), r.phase, parse_phase_unit,
                         "Unit of a phase column: deg or rad (default: from the file's unit)")
           ->check(CLI::IsMember({"deg", "rad"})),
       [](const ReadOptions& f, ReadOptions& t) { t.phase = f.phase; });
  bind(add_parsed_option(app, name("time-convention"), r.time_convention, parse_time_convention,
                         "Time convention of the file: +jwt (engineering, admitgen's) or -jwt (physics, "
                         "e^{-iwt}); default +jwt, checked")
           ->check(CLI::IsMember({"+jwt", "-jwt"})),
       [](const ReadOptions& f, ReadOptions& t) { t.time_convention = f.time_convention; });
  bind(add_clearing_flag(app, name("no-plausibility-errors"), r.plausibility_errors,
                         "Report implausible data (SI suspected, Re y < 0, time convention) as warnings instead of errors"),
       [](const ReadOptions& f, ReadOptions& t) { t.plausibility_errors = f.plausibility_errors; });
  if (!scope.group.empty())
    for (const auto& b : added.bound_) b.option->group(scope.group);
  return added;
}

ReadOptions DataOptions::take_given(const ReadOptions& base, const ReadOptions& given) const {
  ReadOptions out = base;
  for (const auto& b : bound_)
    if (b.option->count() > 0) b.take(given, out);
  return out;
}

void add_tube_options(CLI::App& app, TubeSetup& tube) {
  app.add_option("--tube-diameter", tube.diameter_m, "Tube diameter d [m] (tube_losses, edge_gap, chain effects)");
  app.add_option("--mic-spacing", tube.spacing_m, "Microphone spacing s [m] (chain effects)");
  app.add_option("--mic-distance", tube.mic1_distance_m, "Sample face to the farther microphone x1 [m] (chain effects)");
  app.add_option("--temperature", tube.temperature_c, "Air temperature [C]")->capture_default_str();
}

std::string flag_for(const std::string& key) {
  // Keys are the fields of the settings structs the options bind to (ReadOptions, FitSettings,
  // codegen::EmitSettings, StageRequest, SynthRequest, TubeSetup); a boolean turned off by a "--no-" flag
  // is named with its condition.
  static const std::map<std::string, std::string> flags{
      {"band", "--band"},
      {"columns", "--columns"},
      {"data_count", "--likelihood-k"},
      {"enforce_passivity = false", "--no-passivity-enforcement"},
      {"estimate", "--estimate"},
      {"fidelity_tolerance", "--fidelity-tolerance"},
      {"fir_taps", "--fir-taps"},
      {"format", "--format"},
      {"format.skip_rows", "--skip-rows"},
      {"grid_growth", "--grid-growth"},
      {"fs_hz", "--fs"},
      {"magnitude", "--magnitude"},
      {"max_buffers", "--max-buffers"},
      {"name", "--name"},
      {"noise_std", "--noise"},
      {"order", "--order"},
      {"passive", "--passive"},
      {"phase", "--phase-unit"},
      {"points", "--points"},
      {"priors", "--priors"},
      {"admittance_scale", "--admittance-scale"},
      {"prior", "--prior"},
      {"qmax", "--qmax"},
      {"quantity", "--quantity"},
      {"reduce_symmetry = false", "--no-symmetry-reduction"},
      {"rho_c", "--rho-c"},
      {"rule", "--select"},
      {"runs", "--runs"},
      {"sampler.live", "--live"},
      {"sampler_kind", "--sampler"},
      {"smax", "--smax"},
      {"target.max_band_delta_alpha", "--target-alpha"},
      {"target.max_relative_rms", "--target-rms"},
      {"time_convention", "--time-convention"},
      {"tube.diameter_m", "--tube-diameter"},
      {"tube.mic1_distance_m", "--mic-distance"},
      {"tube.spacing_m", "--mic-spacing"},
  };
  // The reading options of diagnose's --sim table (DiagnoseCommand::sim_read): "sim.columns" -> "--sim-columns".
  if (key.rfind("sim.", 0) == 0) {
    const std::string flag = flag_for(key.substr(4));
    return flag.rfind("--", 0) == 0 ? "--sim-" + flag.substr(2) : key;
  }
  const auto it = flags.find(key);
  return it == flags.end() ? key : it->second;
}

std::string spelled(const std::string& text) { return spell_settings(text, flag_for, " "); }

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
#include "cli/options.hpp"

#include <map>
#include <vector>

namespace admitgen::cli {

CLI::Option* add_clearing_flag(CLI::App& app, const std::string& name, bool& field, const std::string& help) {
  return app.add_flag_callback(name, [&field] { field = false; }, help);
}

namespace {

/// The data options by the name after "--" and the field of ReadOptions each sets (with_given_options
/// copies it); add_data_options registers the same names.
struct DataField {
  std::vector<const char*> names;
  void (*take)(const ReadOptions& from, ReadOptions& to);
};

const std::vector<DataField>& data_fields() {
  static const std::vector<DataField> fields{
      {{"columns"}, [](const ReadOptions& f, ReadOptions& t) { t.columns = f.columns; }},
      {{"quantity"}, [](const ReadOptions& f, ReadOptions& t) { t.quantity = f.quantity; }},
      {{"normalized", "normalised", "rho-c"}, [](const ReadOptions& f, ReadOptions& t) { t.rho_c = f.rho_c; }},
      {{"band"}, [](const ReadOptions& f, ReadOptions& t) { t.band = f.band; }},
      {{"delimiter"}, [](const ReadOptions& f, ReadOptions& t) { t.format.delimiter = f.format.delimiter; }},
      {{"decimal"}, [](const ReadOptions& f, ReadOptions& t) { t.format.decimal = f.format.decimal; }},
      {{"skip-rows"}, [](const ReadOptions& f, ReadOptions& t) { t.format.skip_rows = f.format.skip_rows; }},
      {{"magnitude"}, [](const ReadOptions& f, ReadOptions& t) { t.magnitude = f.magnitude; }},
      {{"phase-unit"}, [](const ReadOptions& f, ReadOptions& t) { t.phase = f.phase; }},
      {{"time-convention"}, [](const ReadOptions& f, ReadOptions& t) { t.time_convention = f.time_convention; }},
      {{"no-plausibility-errors"},
       [](const ReadOptions& f, ReadOptions& t) { t.plausibility_errors = f.plausibility_errors; }},
  };
  return fields;
}

}  // namespace

void add_data_options(CLI::App& app, ReadOptions& r, const DataOptionScope& scope) {
  const auto name = [&scope](const char* option) { return "--" + scope.prefix + option; };
  std::vector<CLI::Option*> added;
  added.push_back(add_parsed_option(
      app, name("columns"), r.columns, ColumnMap::parse,
      "What each column holds, by position (f, re, im, mag, phase, _ to skip; e.g. f,_,_,_,_,re,im,_) or by "
      "header name (e.g. \"f=Frequency [Hz],re=Re(Z/Z0),im=Im(Z/Z0)\"); default: from the header's names, "
      "else f,re,im"));
  added.push_back(add_parsed_option(app, name("quantity"), r.quantity, parse_quantity,
                                    "What the values are (default: from the header's names, else admittance)")
                      ->check(CLI::IsMember({"admittance", "impedance", "reflection"})));
  // Normalised is what an empty rho_c means: the flag only states it (and excludes --rho-c).
  auto* norm = app.add_flag(name("normalized") + "," + name("normalised"), "Values are normalised by rho0*c0 (default)");
  added.push_back(norm);
  added.push_back(
      app.add_option(name("rho-c"), r.rho_c, "Values are SI; divide out this rho0*c0 [Pa s/m] (e.g. 413.3)")->excludes(norm));
  added.push_back(add_parsed_option(app, name("band"), r.band, Band::parse, "Keep only FMIN:FMAX [Hz]"));
  // An empty delimiter or decimal separator is sniffed from the file ("auto").
  added.push_back(app.add_option_function<std::string>(
                         name("delimiter"),
                         [&r](const std::string& t) {
                           if (t != "auto") r.format.delimiter = t == "tab" ? '\t' : t == "space" ? ' ' : t[0];
                         },
                         "Field separator: auto (sniffed), ',', ';', tab or space (runs of blanks)")
                      ->check(CLI::IsMember({"auto", ",", ";", "tab", "space"}))
                      ->default_str("auto"));
  added.push_back(app.add_option_function<std::string>(
                         name("decimal"), [&r](const std::string& t) { if (t != "auto") r.format.decimal = t[0]; },
                         "Decimal separator: auto (sniffed), '.' or ','")
                      ->check(CLI::IsMember({"auto", ".", ","}))
                      ->default_str("auto"));
  added.push_back(app.add_option(name("skip-rows"), r.format.skip_rows,
                                 "Lines to skip before reading (preamble lines are also detected)")
                      ->check(CLI::NonNegativeNumber)
                      ->capture_default_str());
  added.push_back(add_parsed_option(app, name("magnitude"), r.magnitude, parse_magnitude_scale,
                                    "Scale of a mag column: linear or db (20 log10); default from the unit, else linear")
                      ->check(CLI::IsMember({"linear", "db"})));
  added.push_back(add_parsed_option(app, name("phase-unit"), r.phase, parse_phase_unit,
                                    "Unit of a phase column: deg or rad (default: from the file's unit)")
                      ->check(CLI::IsMember({"deg", "rad"})));
  added.push_back(add_parsed_option(app, name("time-convention"), r.time_convention, parse_time_convention,
                                    "Time convention of the file: +jwt (engineering, admitgen's) or -jwt (physics, "
                                    "e^{-iwt}); default +jwt, checked")
                      ->check(CLI::IsMember({"+jwt", "-jwt"})));
  added.push_back(add_clearing_flag(
      app, name("no-plausibility-errors"), r.plausibility_errors,
      "Report implausible data (SI suspected, Re y < 0, time convention) as warnings instead of errors"));
  if (!scope.group.empty())
    for (CLI::Option* o : added) o->group(scope.group);
}

ReadOptions with_given_options(const CLI::App& app, const std::string& prefix, const ReadOptions& base,
                               const ReadOptions& given) {
  ReadOptions out = base;
  for (const DataField& field : data_fields())
    for (const char* n : field.names)
      if (app.count("--" + prefix + n) > 0) {
        field.take(given, out);
        break;
      }
  return out;
}

void add_tube_options(CLI::App& app, TubeSetup& tube) {
  app.add_option("--tube-diameter", tube.diameter_m, "Tube diameter d [m] (tube_losses, edge_gap, chain effects)");
  app.add_option("--mic-spacing", tube.spacing_m, "Microphone spacing s [m] (chain effects)");
  app.add_option("--mic-distance", tube.mic1_distance_m, "Sample face to the farther microphone x1 [m] (chain effects)");
  app.add_option("--temperature", tube.temperature_c, "Air temperature [C]")->capture_default_str();
}

std::string flag_for(const std::string& key) {
  static const std::map<std::string, std::string> flags{
      {"band", "--band"},
      {"columns", "--columns"},
      {"data_count", "--likelihood-k"},
      {"format.skip_rows", "--skip-rows"},
      {"magnitude", "--magnitude"},
      {"noise_std", "--noise"},
      {"phase", "--phase-unit"},
      {"points", "--points"},
      {"qmax", "--qmax"},
      {"quantity", "--quantity"},
      {"reduce_symmetry = false", "--no-symmetry-reduction"},
      {"rho_c", "--rho-c"},
      {"rule", "--select"},
      {"sampler_kind", "--sampler"},
      {"smax", "--smax"},
      {"time_convention", "--time-convention"},
      {"tube.diameter_m", "--tube-diameter"},
      {"tube.mic1_distance_m", "--mic-distance"},
      {"tube.spacing_m", "--mic-spacing"},
  };
  const auto it = flags.find(key);
  return it == flags.end() ? key : it->second;
}

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
#include "cli/data_options.hpp"

#include "core/errors.hpp"

namespace admitgen::cli {

void add_data_options(CLI::App& app, DataOptions& o) {
  app.add_option("--columns", o.columns,
                 "What each column holds, by position (f, re, im, mag, phase, _ to skip; e.g. f,_,_,_,_,re,im,_) or by "
                 "header name (e.g. \"f=Frequency [Hz],re=Re(Z/Z0),im=Im(Z/Z0)\"); default: from the header's names, "
                 "else f,re,im");
  app.add_option("--quantity", o.quantity, "What the values are (default: from the header's names, else admittance)")
      ->check(CLI::IsMember({"admittance", "impedance", "reflection"}));
  auto* norm = app.add_flag("--normalized,--normalised", o.normalized, "Values are normalised by rho0*c0 (default)");
  app.add_option("--rho-c", o.rho_c, "Values are SI; divide out this rho0*c0 [Pa s/m] (e.g. 413.3)")->excludes(norm);
  app.add_option("--band", o.band, "Keep only FMIN:FMAX [Hz]");
  app.add_option("--delimiter", o.delimiter, "Field separator: auto (sniffed), ',', ';', tab or space (runs of blanks)")
      ->check(CLI::IsMember({"auto", ",", ";", "tab", "space"}))
      ->capture_default_str();
  app.add_option("--decimal", o.decimal, "Decimal separator: auto (sniffed), '.' or ','")
      ->check(CLI::IsMember({"auto", ".", ","}))
      ->capture_default_str();
  app.add_option("--skip-rows", o.skip_rows, "Lines to skip before reading (preamble lines are also detected)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--magnitude", o.magnitude, "Scale of a mag column: linear or db (20 log10); default from the unit, else linear")
      ->check(CLI::IsMember({"linear", "db"}));
  app.add_option("--phase-unit", o.phase_unit, "Unit of a phase column: deg or rad (default: from the file's unit)")
      ->check(CLI::IsMember({"deg", "rad"}));
  app.add_option("--time-convention", o.time_convention,
                 "Time convention of the file: +jwt (engineering, admitgen's) or -jwt (physics, e^{-iwt}); default "
                 "+jwt, checked")
      ->check(CLI::IsMember({"+jwt", "-jwt"}));
  app.add_flag("--no-plausibility-errors", o.no_plausibility_errors,
               "Report implausible data (SI suspected, Re y < 0, time convention) as warnings instead of errors");
}

ReadOptions DataOptions::to_read_options() const {
  ReadOptions r;
  if (columns) r.columns = ColumnMap::parse(*columns);
  if (quantity) r.quantity = parse_quantity(*quantity);
  r.rho_c = rho_c;
  if (band) r.band = Band::parse(*band);
  if (delimiter != "auto") r.format.delimiter = delimiter == "tab" ? '\t' : delimiter == "space" ? ' ' : delimiter[0];
  if (decimal != "auto") r.format.decimal = decimal[0];
  r.format.skip_rows = skip_rows;
  if (magnitude) r.magnitude = parse_magnitude_scale(*magnitude);
  if (phase_unit) r.phase = parse_phase_unit(*phase_unit);
  if (time_convention) r.time_convention = parse_time_convention(*time_convention);
  r.plausibility_errors = !no_plausibility_errors;
  return r;
}

}  // namespace admitgen::cli

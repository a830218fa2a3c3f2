#include "cli/data_options.hpp"

#include "core/errors.hpp"

namespace admitgen::cli {

void add_data_options(CLI::App& app, DataOptions& o) {
  app.add_option("--columns", o.columns,
                 "What each column holds: f, re, im, or _ to skip (e.g. f,_,_,_,_,re,im,_ for the shared Basotect "
                 "files)")
      ->capture_default_str();
  app.add_option("--quantity", o.quantity, "What re/im are")
      ->check(CLI::IsMember({"admittance", "impedance", "reflection"}))
      ->capture_default_str();
  auto* norm = app.add_flag("--normalized,--normalised", o.normalized, "Values are normalised by rho0*c0 (default)");
  app.add_option("--rho-c", o.rho_c, "Values are SI; divide out this rho0*c0 [Pa s/m] (e.g. 413.3)")->excludes(norm);
  app.add_option("--band", o.band, "Keep only FMIN:FMAX [Hz]");
}

ReadOptions DataOptions::to_read_options() const {
  ReadOptions r;
  r.columns = ColumnMap::parse(columns);
  r.quantity = parse_quantity(quantity);
  r.rho_c = rho_c;
  if (band) r.band = Band::parse(*band);
  return r;
}

}  // namespace admitgen::cli

// SPDX-License-Identifier: MIT
/// @file
/// A material library (docs/library.md): materials, each one `admitgen fit` of a data file followed by one
/// `admitgen emit`, planned as work units that run anywhere and merge into the same files a single machine
/// writes.
///
/// A work unit is one order of one material's grid: fit_order(data, order, settings, round 0), the entry of
/// run_first_round (selection/fit.hpp) for that order. Its seed stream is order_seed(seed, order), which does
/// not depend on the grid, the thread count or the machine, so a unit computed on a cluster node is the
/// entry a plain `fit` computes. The merge runs complete_fit on the units (the re-runs of orders that missed
/// a mode, which depend on several orders, run there), then writes what `fit` and `emit` write.
///
/// A unit is up to date when its result file holds the key of its current inputs: sha256 of the admitgen
/// version, the data file's bytes, the options the unit depends on (Material::unit_inputs) and the order.
#pragma once

#include "codegen/emission.hpp"
#include "core/progress.hpp"
#include "data/read_options.hpp"
#include "model/order.hpp"
#include "selection/fit.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace admitgen::library {

struct Material {
  std::string name;  ///< [A-Za-z0-9_] only: a folder name and part of C identifiers
  long line = 0;     ///< where the manifest declares it
  std::string data;  ///< the data file's path (the manifest's folder joined to data_as_written)
  /// The path as the manifest writes it, relative to the manifest's folder: what fit.json records, as a
  /// plain `admitgen fit` run in that folder records it.
  std::string data_as_written;
  ReadOptions read;
  FitSettings fit;  ///< priors_origin: the prior file's path as the manifest writes it
  codegen::EmitSettings emit;  ///< emit.name: the prefix of its tables in the headers
  /// Everything besides the data and the order that a unit's run depends on, in one canonical text (the
  /// reading and sampling options and the prior file's sha256; not qmax/smax, the selection rule nor the
  /// re-run rounds, which only the merge uses).
  std::string unit_inputs;
  /// The equivalent command lines (for the plan and the docs: a material is exactly these two commands).
  std::string fit_command, emit_command;
};

struct Library {
  std::string manifest;  ///< the manifest's path
  std::string name;      ///< C prefix of the library header (DIR/NAME.h)
  std::vector<Material> materials;
};

struct WorkUnit {
  std::size_t material = 0;
  Order order{0, 0};
  std::string id;    ///< "MATERIAL/QxSy"
  std::string key;   ///< sha256 of its inputs (file comment)
  std::string path;  ///< its result file, DIR/units/MATERIAL/QxSy.unit
  bool up_to_date = false;
};

/// Every unit of `library` in manifest order, then grid order; `dir` is the library's output folder.
std::vector<WorkUnit> plan_units(const Library& library, const std::string& dir);

/// The plan as text: one line per unit (id, state, key prefix), then the totals.
std::string plan_text(const std::vector<WorkUnit>& units);

/// Runs one unit and writes its result file atomically (io/unit_file.hpp).
void run_unit(const Library& library, const WorkUnit& unit);

/// Runs the units not up to date on `threads` workers (0 = all cores), largest order first; returns how
/// many ran. Each result file is written as soon as its unit ends, so an interrupted run loses only the
/// units still running.
std::size_t run_units(const Library& library, const std::vector<WorkUnit>& units, int threads, Progress& progress);

/// Reads every material's units (all must be up to date, else InputError naming them and what to run),
/// completes each fit, and writes DIR/materials/NAME/ (fit.json, posterior files, report.html, NAME.h,
/// bands.json) and the library files (NAME.h of all materials, bands.json, bands.csv, report.html; see
/// library/exports.hpp). A material whose header fails admitgen check stops the merge before the library
/// files are written. `threads` merges that many materials at once (0 = all cores); the outputs do not
/// depend on it.
void merge(const Library& library, const std::string& dir, const std::string& template_text, int threads,
           Progress& progress);

}  // namespace admitgen::library

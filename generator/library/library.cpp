// SPDX-License-Identifier: MIT
#include "library/library.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "core/sha256.hpp"
#include "core/version.hpp"
#include "data/csv_reader.hpp"
#include "emit/emit.hpp"
#include "io/bands_file.hpp"
#include "io/fit_file.hpp"
#include "inference/comparison.hpp"
#include "io/unit_file.hpp"
#include "library/exports.hpp"
#include "library/fit_directory.hpp"
#include "selection/fit_cost.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace admitgen::library {
namespace fs = std::filesystem;
namespace {

/// A material's data, recorded under the path the manifest writes (Material::data_as_written).
Measurement read_data(const Material& m) {
  Measurement data = read_measurement(m.data, m.read);
  data.path = m.data_as_written;
  return data;
}

}  // namespace

std::vector<WorkUnit> plan_units(const Library& library, const std::string& dir) {
  std::vector<WorkUnit> units;
  for (std::size_t i = 0; i < library.materials.size(); ++i) {
    const Material& m = library.materials[i];
    const std::string data_sha = sha256_file_hex(m.data);
    for (const Order& order : order_grid(m.fit.qmax, m.fit.smax)) {
      WorkUnit u;
      u.material = i;
      u.order = order;
      u.id = m.name + "/" + order.name();
      u.key = sha256_hex(fmt::format("admitgen {}\ndata {}\n{}\norder {}\n", kVersion, data_sha, m.unit_inputs,
                                     order.name()));
      u.path = (fs::path(dir) / "units" / m.name / (order.name() + ".unit")).string();
      u.up_to_date = io::unit_file_key(u.path) == u.key;
      units.push_back(std::move(u));
    }
  }
  return units;
}

std::string plan_text(const std::vector<WorkUnit>& units) {
  std::string out;
  std::size_t done = 0;
  for (const auto& u : units) {
    out += fmt::format("{:<32} {:<10} {}\n", u.id, u.up_to_date ? "up-to-date" : "to-run", u.key.substr(0, 12));
    done += u.up_to_date ? 1 : 0;
  }
  out += fmt::format("{} units: {} up to date, {} to run\n", units.size(), done, units.size() - done);
  return out;
}

void run_unit(const Library& library, const WorkUnit& unit) {
  const Material& m = library.materials.at(unit.material);
  const Measurement data = read_data(m);
  io::UnitResult result{unit.key, fit_order(data, unit.order, m.fit)};
  ensure_writable_directory(fs::path(unit.path).parent_path().string());
  write_file_atomically(unit.path, io::unit_text(result));
}

std::size_t run_units(const Library& library, const std::vector<WorkUnit>& units, int threads, Progress& progress) {
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < units.size(); ++i)
    if (!units[i].up_to_date) queue.push_back(i);
  // Largest order first (as a fit orders its grid): the longest runs start early.
  std::stable_sort(queue.begin(), queue.end(),
                   [&](std::size_t a, std::size_t b) { return units[a].order.dim() > units[b].order.dim(); });
  // Each material's data are read once.
  std::map<std::size_t, Measurement> data;
  for (std::size_t i : queue)
    if (!data.count(units[i].material)) {
      const Material& m = library.materials[units[i].material];
      data.emplace(units[i].material, read_data(m));
    }
  // The units on the comparison driver (inference/comparison.hpp), each at the work a fit expects of its order.
  std::vector<ComparisonJob> jobs;
  for (const WorkUnit& u : units) {
    const FitSettings& fit = library.materials[u.material].fit;
    jobs.push_back({u.id, expected_work(u.order, fit, fit.sampler.live), fit.sampler.stop_dlogz()});
  }
  std::vector<double> log_z(units.size()), error(units.size());
  Comparison comparison(progress, threads, "units");
  comparison.run(
      jobs, queue,
      [&](std::size_t i, const NestedProgressFn& status) {
        const WorkUnit& u = units[i];
        const Material& m = library.materials[u.material];
        io::UnitResult result{u.key, fit_order(data.at(u.material), u.order, m.fit, status)};
        ensure_writable_directory(fs::path(u.path).parent_path().string());
        write_file_atomically(u.path, io::unit_text(result));
        log_z[i] = result.model.run.log_z;
        error[i] = result.model.run.log_z_error;
      },
      [&](std::size_t i, const TaskTime& time) {
        return fmt::format("  {:<32} ln Z = {:10.2f} ± {:.2f}  ({:.1f} s)", units[i].id, log_z[i], error[i],
                           time.seconds);
      });
  return queue.size();
}

void merge(const Library& library, const std::string& dir, const std::string& template_text, int threads,
           Progress& progress) {
  const std::vector<WorkUnit> units = plan_units(library, dir);
  std::vector<std::string> missing;
  for (const auto& u : units)
    if (!u.up_to_date) missing.push_back(u.id);
  if (!missing.empty())
    throw InputError(fmt::format("{} of {} units have no current result ({}{}): run `admitgen library run {}` or "
                                 "`admitgen library slurm {}` first",
                                 missing.size(), units.size(), missing.front(), missing.size() > 1 ? ", ..." : "", dir,
                                 dir));
  // Materials in parallel, each writing only its own folder and output slot (their re-runs of missed modes
  // then run on one thread each: results never depend on threads).
  std::vector<MaterialOutput> outputs(library.materials.size());
  std::vector<std::size_t> queue(library.materials.size());
  for (std::size_t i = 0; i < queue.size(); ++i) queue[i] = i;
  run_in_parallel(queue, threads, [&](std::size_t i) {
    const Material& m = library.materials[i];
    const Measurement data = read_data(m);
    std::vector<ModelResult> first_round;
    for (const auto& u : units)
      if (u.material == i) {
        io::UnitResult r = io::read_unit_file(u.path);
        if (r.key != u.key || r.model.order != u.order)
          throw FileError(u.path, 0, "unit file changed while merging", r.key);
        first_round.push_back(std::move(r.model));
      }
    FitSettings settings = m.fit;
    settings.threads = 1;
    Progress quiet(false);
    const FitResult fit = complete_fit(data, settings, std::move(first_round), quiet);
    const fs::path out = fs::path(dir) / "materials" / m.name;
    ensure_writable_directory(out.string());
    write_fit_directory(out.string(), data, m.read, settings, fit);
    // emit exactly as `admitgen emit OUT/fit.json` does: from the file written.
    const std::string fit_path = (out / "fit.json").string();
    const std::string header_name = m.name + ".h";
    emit::EmitResult emitted = emit::emit(io::read_fit_file(fit_path), fit_path, m.emit, template_text, header_name);
    if (!emitted.safe()) throw InputError(emitted.refusal((out / header_name).string()));
    write_file_atomically((out / header_name).string(), emitted.header);
    write_file_atomically((out / "bands.json").string(), io::bands_text(emitted.emission));
    outputs[i] = {m.name, std::move(emitted.emission), std::move(emitted.header), fit.models[fit.selected], fit.warnings};
    progress.message(fmt::format("merged {} ({})", m.name, fit.models[fit.selected].order.name()));
  });
  progress.finish();
  write_library_files(library.name, dir, outputs);
}

}  // namespace admitgen::library

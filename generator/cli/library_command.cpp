// SPDX-License-Identifier: MIT
#include "cli/library_command.hpp"

#include "cli/library_manifest.hpp"
#include "codegen/template_text.hpp"
#include "core/atomic_file.hpp"
#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "core/progress.hpp"
#include "library/library.hpp"
#include "library/slurm.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace admitgen::cli {
namespace {
namespace fs = std::filesystem;

/// DIR/manifest.path: the manifest a planned library folder belongs to (absolute).
std::string manifest_pointer(const std::string& dir) { return (fs::path(dir) / "manifest.path").string(); }

/// The library of a planned folder: its manifest, read again (so an edited data file or manifest is seen).
library::Library planned_library(const std::string& dir) {
  const std::string pointer = manifest_pointer(dir);
  if (!fs::exists(pointer))
    throw InputError(fmt::format("{} is not a planned library folder (no manifest.path): run `admitgen library plan "
                                 "MANIFEST --out {}` first", dir, dir));
  std::string path = read_bounded(pointer, 1 << 16, "manifest.path");
  while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
  return read_manifest(path);
}

struct LibraryOptions {
  std::string manifest, dir, unit;
  int threads = 0;
  bool quiet = false;
  std::string templates;
  library::SlurmOptions slurm;
};

int run_plan(const LibraryOptions& o) {
  const library::Library lib = read_manifest(o.manifest);  // all checked before anything is written
  const auto units = library::plan_units(lib, o.dir);
  ensure_writable_directory(o.dir);
  write_file_atomically(manifest_pointer(o.dir), fs::absolute(o.manifest).lexically_normal().string() + "\n");
  std::string text;
  for (const auto& m : lib.materials) text += fmt::format("# {}: {}\n#   then {}\n", m.name, m.fit_command, m.emit_command);
  text += library::plan_text(units);
  write_file_atomically((fs::path(o.dir) / "plan.txt").string(), text);
  if (!o.quiet) fmt::print("{}", text);
  return 0;
}

int run_local(const LibraryOptions& o) {
  const library::Library lib = planned_library(o.dir);
  const auto units = library::plan_units(lib, o.dir);
  Progress progress(!o.quiet);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t ran = library::run_units(lib, units, o.threads, progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet)
    fmt::print("ran {} of {} units in {:.1f} s ({} already up to date)\n", ran, units.size(), seconds, units.size() - ran);
  return 0;
}

int run_one_unit(const LibraryOptions& o) {
  const library::Library lib = planned_library(o.dir);
  for (const auto& u : library::plan_units(lib, o.dir))
    if (u.id == o.unit) {
      if (u.up_to_date) {
        if (!o.quiet) fmt::print("{} is up to date\n", u.id);
        return 0;
      }
      library::run_unit(lib, u);
      if (!o.quiet) fmt::print("{} done: {}\n", u.id, u.path);
      return 0;
    }
  throw InputError(fmt::format("no unit '{}' in the library of {} (units are MATERIAL/QxSy; see plan.txt)", o.unit, o.dir));
}

int run_merge(const LibraryOptions& o) {
  const library::Library lib = planned_library(o.dir);
  Progress progress(!o.quiet);
  library::merge(lib, o.dir, codegen::load_template(o.templates, "admitgen_boundary.h.in"), o.threads, progress);
  if (!o.quiet)
    fmt::print("merged {} materials: {}/{}.h, bands.json, bands.csv, report.html; per material materials/NAME/\n",
               lib.materials.size(), o.dir, lib.name);
  return 0;
}

int run_slurm(const LibraryOptions& o) {
  const library::Library lib = planned_library(o.dir);
  const auto units = library::plan_units(lib, o.dir);
  library::SlurmOptions s = o.slurm;
  s.admitgen = fs::read_symlink("/proc/self/exe").string();
  const library::SlurmSubmission sub = library::submit_to_slurm(units, o.dir, s);
  if (!o.quiet) {
    for (const auto& c : sub.commands) fmt::print("{}{}\n", s.dry_run ? "would run: " : "ran: ", c);
    fmt::print("{} of {} units submitted{}{}\n", sub.units, units.size(),
               sub.array_job.empty() ? "" : " as array job " + sub.array_job,
               sub.merge_job.empty() ? "" : "; merge job " + sub.merge_job);
  }
  if (!s.dry_run) fmt::print("{}\n", sub.merge_job);  // the job to wait for (last line)
  return 0;
}

}  // namespace

void setup_library_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<LibraryOptions>();
  auto* lib = app.add_subcommand("library", "A material library: plan, run (locally or on Slurm) and merge many fits");
  lib->require_subcommand(1);
  lib->footer("Laptop:  admitgen library plan walls.toml --out lib && admitgen library run lib && admitgen library merge lib\n"
              "Cluster: admitgen library plan walls.toml --out lib && admitgen library slurm lib\n"
              "(docs/library.md: the manifest, work units, outputs)");
  auto* plan = lib->add_subcommand("plan", "Read the manifest, list the work units and which are up to date");
  plan->add_option("manifest", o->manifest, "Library manifest (TOML)")->required()->check(CLI::ExistingFile);
  plan->add_option("--out,-o", o->dir, "Library folder (created if missing)")->required();
  plan->add_flag("--quiet,-q", o->quiet, "Print nothing");
  plan->callback([o, &exit_code] { exit_code = run_plan(*o); });

  auto* run = lib->add_subcommand("run", "Run the units not up to date on this machine");
  run->add_option("dir", o->dir, "Library folder (admitgen library plan)")->required();
  run->add_option("--threads,-j", o->threads, "Worker threads (0 = all cores); results do not depend on it")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  run->add_flag("--quiet,-q", o->quiet, "No progress or summary output");
  run->callback([o, &exit_code] { exit_code = run_local(*o); });

  auto* unit = lib->add_subcommand("unit", "Run one unit (what each Slurm array task runs)");
  unit->add_option("dir", o->dir, "Library folder")->required();
  unit->add_option("unit", o->unit, "The unit, MATERIAL/QxSy")->required();
  unit->add_flag("--quiet,-q", o->quiet, "Print nothing");
  unit->callback([o, &exit_code] { exit_code = run_one_unit(*o); });

  auto* merge = lib->add_subcommand("merge", "Assemble, emit and check every material; write the library's exports");
  merge->add_option("dir", o->dir, "Library folder")->required();
  merge->add_option("--threads,-j", o->threads, "Materials merged at once (0 = all cores); results do not depend on it")
      ->check(CLI::Range(0, 1024))->capture_default_str();
  merge->add_option("--templates", o->templates, "Directory holding admitgen_boundary.h.in (default: built in)");
  merge->add_flag("--quiet,-q", o->quiet, "No progress or summary output");
  merge->callback([o, &exit_code] { exit_code = run_merge(*o); });

  auto* slurm = lib->add_subcommand("slurm", "Submit the units not up to date as a Slurm job array, and the merge after it");
  slurm->add_option("dir", o->dir, "Library folder")->required();
  slurm->add_option("--sbatch", o->slurm.sbatch, "Extra sbatch option for both jobs (repeatable), e.g. --sbatch=--partition=short");
  slurm->add_option("--merge-threads", o->slurm.merge_threads, "CPUs of the merge job")->check(CLI::Range(1, 1024))->capture_default_str();
  slurm->add_flag("--dry-run", o->slurm.dry_run, "Write the job scripts and print the sbatch commands; submit nothing");
  slurm->add_flag("--quiet,-q", o->quiet, "Print only the merge job's id");
  slurm->callback([o, &exit_code] { exit_code = run_slurm(*o); });
}

}  // namespace admitgen::cli

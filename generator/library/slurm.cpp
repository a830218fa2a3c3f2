// SPDX-License-Identifier: MIT
#include "library/slurm.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/text.hpp"

#include <fmt/format.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>

namespace admitgen::library {
namespace fs = std::filesystem;
namespace {

/// Runs `command` through the shell; its output (stderr merged) and exit status.
std::pair<std::string, int> run_status(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw InputError(fmt::format("cannot run '{}'", command));
  std::string out;
  std::array<char, 4096> buffer{};
  while (const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) out.append(buffer.data(), n);
  return {out, pclose(pipe)};
}

/// Runs `command` through the shell; returns its stdout (stderr merged). Throws InputError on failure.
std::string run(const std::string& command) {
  auto [out, status] = run_status(command);
  if (status != 0)
    throw InputError(fmt::format("'{}' failed (exit status {}): {}", command,
                                 WIFEXITED(status) ? WEXITSTATUS(status) : status, out));
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out.substr(0, out.find(';'));  // --parsable: "JOBID" or "JOBID;CLUSTER"
}

/// Refuses a new submission while a job of an earlier one is still queued or running (its pending tasks
/// would run units a second time): the job ids come from DIR/slurm/submitted-N.txt.
void refuse_while_queued(const fs::path& slurm) {
  for (int n = 1; fs::exists(slurm / fmt::format("submitted-{}.txt", n)); ++n) {
    std::ifstream in(slurm / fmt::format("submitted-{}.txt", n));
    std::string kind, id;
    while (in >> kind && std::getline(in, id)) {
      id = std::string(trim(id, " "));
      if ((kind != "array" && kind != "merge") || id.empty()) continue;
      const auto [out, status] = run_status("squeue -h -o %i -j " + id);
      if (status == 0 && out.find_first_not_of(" \n") != std::string::npos)
        throw InputError(fmt::format("the {} job {} of submission {} is still queued or running: wait for it, or "
                                     "scancel {} and submit again (only units without a result are submitted)",
                                     kind, id, n, id));
    }
  }
}

/// The next free submission number under DIR/slurm (submissions are kept, numbered from 1).
int next_submission(const fs::path& slurm) {
  int n = 1;
  while (fs::exists(slurm / fmt::format("units-{}.list", n)) || fs::exists(slurm / fmt::format("merge-{}.sh", n))) ++n;
  return n;
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

SlurmSubmission submit_to_slurm(const std::vector<WorkUnit>& units, const std::string& dir, const SlurmOptions& o) {
  const fs::path root = fs::absolute(dir);
  const fs::path slurm = root / "slurm";
  ensure_writable_directory((slurm / "logs").string());
  if (!o.dry_run) refuse_while_queued(slurm);
  const int n = next_submission(slurm);
  SlurmSubmission s;
  std::string list;
  for (const auto& u : units)
    if (!u.up_to_date) {
      list += u.id + "\n";
      ++s.units;
    }
  std::string extra;
  for (const auto& a : o.sbatch) extra += " " + shell_quote(a);
  const std::string exe = shell_quote(o.admitgen), where = shell_quote(root.string());
  if (s.units > 0) {
    s.unit_list = (slurm / fmt::format("units-{}.list", n)).string();
    s.units_script = (slurm / fmt::format("units-{}.sh", n)).string();
    write_file_atomically(s.unit_list, list);
    write_file_atomically(
        s.units_script,
        fmt::format(R"SH(#!/bin/sh
# One work unit of the library in {} per array task (admitgen library slurm, submission {}).
#SBATCH --job-name=admitgen-units
#SBATCH --cpus-per-task=1
#SBATCH --output={}/unit-%A_%a.out
set -eu
unit=$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" {})
exec {} library unit {} "$unit"
)SH",
                    root.string(), n, (slurm / "logs").string(), shell_quote(s.unit_list), exe, where));
  }
  s.merge_script = (slurm / fmt::format("merge-{}.sh", n)).string();
  write_file_atomically(s.merge_script,
                        fmt::format(R"SH(#!/bin/sh
# The merge of the library in {} (admitgen library slurm, submission {}).
#SBATCH --job-name=admitgen-merge
#SBATCH --cpus-per-task={}
#SBATCH --output={}/merge-%j.out
set -eu
exec {} library merge {} --threads {}
)SH",
                                    root.string(), n, o.merge_threads, (slurm / "logs").string(), exe, where,
                                    o.merge_threads));
  if (s.units > 0) {
    s.commands.push_back(fmt::format(R"SH(sbatch --parsable{} --array=0-{} {})SH", extra, s.units - 1, shell_quote(s.units_script)));
    if (!o.dry_run) s.array_job = run(s.commands.back());
  }
  const std::string dependency =
      s.units == 0 ? "" : R"SH( --dependency=afterok:)SH" + (o.dry_run ? std::string("ARRAY_JOB_ID") : s.array_job);
  s.commands.push_back(fmt::format(R"SH(sbatch --parsable{}{} {})SH", extra, dependency, shell_quote(s.merge_script)));
  if (!o.dry_run) s.merge_job = run(s.commands.back());
  if (!o.dry_run)
    write_file_atomically((slurm / fmt::format("submitted-{}.txt", n)).string(),
                          fmt::format("array {}\nmerge {}\nunits {}\n", s.array_job, s.merge_job, s.units));
  return s;
}

}  // namespace admitgen::library

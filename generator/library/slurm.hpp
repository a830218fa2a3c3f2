// SPDX-License-Identifier: MIT
/// @file
/// Running a library's units on Slurm (docs/library.md, "On a cluster"): one job array with one unit per
/// task (`sbatch --array`), and the merge as a job that starts when every task has succeeded
/// (`--dependency=afterok`). Only units without a current result are submitted, so re-submitting after a
/// failed or cancelled task runs exactly the units still missing; results are written atomically, so a task
/// killed mid-write leaves no partial result.
#pragma once

#include "library/library.hpp"

#include <string>
#include <vector>

namespace admitgen::library {

struct SlurmOptions {
  std::string admitgen;             ///< the admitgen executable the jobs run (absolute path)
  std::vector<std::string> sbatch;  ///< extra sbatch options for both jobs (e.g. --partition=short)
  int merge_threads = 1;            ///< --cpus-per-task of the merge job (its re-runs of missed modes)
  bool dry_run = false;             ///< write the scripts, print the commands, submit nothing
};

struct SlurmSubmission {
  std::string units_script, merge_script, unit_list;  ///< files written under DIR/slurm/
  std::vector<std::string> commands;                  ///< the sbatch commands (as run, or to run)
  std::string array_job, merge_job;                   ///< job ids ("" in a dry run or without pending units)
  std::size_t units = 0;                              ///< units submitted
};

/// The scripts (units and merge) for the units not up to date, submitted unless a dry run. Throws
/// InputError if sbatch fails, with its output, or while a job of an earlier submission of `dir` is still
/// queued or running (its tasks would run units a second time).
SlurmSubmission submit_to_slurm(const std::vector<WorkUnit>& units, const std::string& dir, const SlurmOptions& options);

/// Single-quoted for a POSIX shell.
std::string shell_quote(const std::string& text);

}  // namespace admitgen::library

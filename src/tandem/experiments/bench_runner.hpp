#pragma once
// Running an experiment: every configuration x every seed, on worker threads (one in human time:
// each run takes both cores), each run recorded as one JSON line in OUT/runs.jsonl the moment it
// ends. A run that is already in that file is not run
// again, so an interrupted experiment resumes where it stopped. A shard (--shard K/N, a task of a
// Slurm job array) runs its share of the runs into its own file (runs_folder.hpp);
// merge_shards.hpp puts the shards' runs together.
//
// Threading: each worker owns its collision checker, motion validator and planner; the problem is
// shared read-only. Finished runs go through one mutex that appends to the file and updates the
// progress line. A stop flag (Ctrl-C) interrupts the running planners; interrupted runs are not
// recorded.

#include <array>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "tandem/experiments/experiment.hpp"
#include "tandem/experiments/runs_folder.hpp"
#include "tandem/planning/tree.hpp"
#include "tandem/runs/run_record.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct BenchOptions {
  std::filesystem::path out_dir;
  unsigned jobs = 2;  ///< runs at once, in virtual time (human time: one)
  /// Overrides the experiment's number of seeds (e.g. a quick look with 3).
  std::optional<std::uint64_t> seeds;
  /// Set by another thread (a signal handler) to stop: running planners are interrupted.
  const std::atomic<bool>* stop = nullptr;
  /// Where the progress bar goes (nullptr: nowhere); live redraws one line with '\r'.
  std::ostream* progress = nullptr;
  bool live_progress = false;
  /// Runs only this shard's share, into OUT/shards/shard-K-of-N.jsonl; runs already in that file
  /// or in OUT/runs.jsonl are not run again.
  std::optional<Shard> shard;
};

struct BenchResult {
  /// The experiment's runs that are recorded (a shard's: its own), in configuration order, then
  /// seed order.
  std::vector<RunRecord> records;
  std::size_t planned = 0;  ///< configurations x seeds (a shard: its share)
  std::size_t resumed = 0;  ///< found in runs.jsonl
  std::size_t ran = 0;      ///< run now
  bool interrupted = false;
  double wall_s = 0.0;
};

/// Runs what is missing from OUT/runs.jsonl. Throws InputError for an output folder that holds
/// another experiment's runs (another problem or time limit), or a configuration the problem
/// cannot run (checked before any run starts).
BenchResult run_experiment(const Experiment& experiment, const Problem& problem,
                           const BenchOptions& options);

/// The records of OUT/runs.jsonl (complete lines only).
std::vector<RunRecord> read_records(const std::filesystem::path& runs_file);

}  // namespace tandem

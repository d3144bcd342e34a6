#pragma once
// Running an experiment: every configuration x every seed, on worker threads, each run recorded as
// one JSON line in OUT/runs.jsonl the moment it ends. A run that is already in that file is not run
// again, so an interrupted experiment resumes where it stopped.
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
#include "tandem/planning/tree.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

/// One run of an experiment: what was run and what came out.
struct RunRecord {
  std::string problem;
  std::string config;                         ///< RunConfig::label()
  std::map<std::string, std::string> params;  ///< the configuration's values, as text
  std::uint64_t seed = 0;
  double time_limit_s = 0.0;
  std::string status;  ///< to_string(PlannerStatus)
  bool solved = false;
  bool path_valid = false;  ///< the solution passed check_path (false when not solved)
  double time_s = 0.0;
  std::uint64_t iterations = 0;
  std::size_t nodes = 0;
  std::size_t edges = 0;
  std::uint64_t collision_checks = 0;
  std::array<std::size_t, kNodeSources> nodes_by_source{};
  double path_length = 0.0;  ///< of the planner's (unsimplified) path; 0 when not solved
  std::uint64_t operator_iterations = 0;
  std::uint64_t contact_entries = 0;
  std::uint64_t operator_waits = 0;  ///< RunOutcome::operator_waits
  std::string tree_digest;           ///< hex of RunOutcome::tree_digest

  /// Identifies the run within an experiment: configuration and seed.
  std::string key() const { return config + " #" + std::to_string(seed); }
  /// The value of a parameter as the report shows it ("" if unset).
  std::string param(const std::string& name) const;
};

/// One line of runs.jsonl (no newline).
std::string format_record(const RunRecord& record);
/// nullopt for a line that is not a complete record (e.g. cut short by a kill).
std::optional<RunRecord> parse_record(const std::string& line);

struct BenchOptions {
  std::filesystem::path out_dir;
  unsigned jobs = 2;
  /// Overrides the experiment's number of seeds (e.g. a quick look with 3).
  std::optional<std::uint64_t> seeds;
  /// Set by another thread (a signal handler) to stop: running planners are interrupted.
  const std::atomic<bool>* stop = nullptr;
  /// Where the progress bar goes (nullptr: nowhere); live redraws one line with '\r'.
  std::ostream* progress = nullptr;
  bool live_progress = false;
};

struct BenchResult {
  /// The experiment's runs that are recorded, in configuration order, then seed order.
  std::vector<RunRecord> records;
  std::size_t planned = 0;  ///< configurations x seeds
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

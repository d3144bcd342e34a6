#pragma once
// An experiment's output folder. OUT/runs.jsonl holds the runs of the whole experiment;
// OUT/shards/shard-K-of-N.jsonl holds the runs of shard K of N (tandem bench --shard, one task of
// a Slurm job array). Every file is JSON lines of RunRecord. A run is known by its key
// (configuration and seed); a later record of a key replaces an earlier one.
//
// Shards: the experiment's runs in seed-major order (every configuration of the first seed, then
// of the second, ...) are dealt out in turn, position p to shard p mod N + 1, so that every shard
// gets a share of every configuration and a run belongs to the same shard on any machine.

#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/experiments/experiment.hpp"
#include "tandem/runs/run_record.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

inline constexpr const char* kRunsFile = "runs.jsonl";

/// Shard `index` of `count`, 1-based.
struct Shard {
  unsigned index = 1;
  unsigned count = 1;
};

/// "K/N" with 1 <= K <= N <= 10000; throws InputError naming `option`.
Shard parse_shard(std::string_view text, const std::string& option);
/// OUT/shards/shard-K-of-N.jsonl
std::filesystem::path shard_file(const std::filesystem::path& out_dir, const Shard& shard);
/// The shard (1-based) of `count` that runs the run at `position` of the seed-major order.
unsigned shard_of(std::size_t position, unsigned count);

/// One run of the experiment: its configuration (an index into Experiment::configs) and seed.
struct PlannedRun {
  std::size_t config = 0;
  std::uint64_t seed = 0;
  std::string key;  ///< RunRecord::key()
};

/// Every run of the experiment with `seeds` seeds, seed-major.
std::vector<PlannedRun> planned_runs(const Experiment& experiment, std::uint64_t seeds);

/// The complete records of a runs file (none if it does not exist). With `repair`, a torn last
/// line (a run cut short by a kill) is dropped from the file too, so that appending goes on from
/// a clean end. Throws InputError if a record is of another problem, time limit or clock.
std::vector<RunRecord> load_runs_file(const std::filesystem::path& file, const Problem& problem,
                                      const Experiment& experiment, bool repair, std::ostream* log);

/// Records by key; a later record of a key replaces an earlier one.
void index_records(std::vector<RunRecord>&& records, std::map<std::string, RunRecord>& done);

/// The experiment's recorded runs, in configuration order, then seed order.
std::vector<RunRecord> ordered_records(const Experiment& experiment, std::uint64_t seeds,
                                       const std::map<std::string, RunRecord>& done);

}  // namespace tandem

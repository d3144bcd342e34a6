#pragma once
// Putting an experiment's shards together: the runs of OUT/runs.jsonl and of every
// OUT/shards/*.jsonl become one OUT/runs.jsonl, from which the report and the OMPL log are made as
// after a run on one machine. Merging is idempotent and loses nothing: the shards' files stay, and
// runs of the folder that are not of this experiment's seeds are kept at the end of the file.

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <vector>

#include "tandem/experiments/experiment.hpp"
#include "tandem/experiments/runs_folder.hpp"
#include "tandem/runs/run_record.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem {

struct MergeResult {
  /// The experiment's recorded runs, in configuration order, then seed order.
  std::vector<RunRecord> records;
  std::size_t planned = 0;           ///< configurations x seeds
  std::size_t shard_files = 0;       ///< shard files read
  std::vector<unsigned> incomplete;  ///< shards of `shards` (if given) with runs missing
};

/// Merges into OUT/runs.jsonl (written atomically). `shards` (0: unknown) is the number of shards
/// the experiment was dealt into, for MergeResult::incomplete. Throws InputError for a file of
/// another experiment (see load_runs_file).
MergeResult merge_shards(const Experiment& experiment, const Problem& problem,
                         const std::filesystem::path& out_dir, std::uint64_t seeds, unsigned shards,
                         std::ostream* log);

}  // namespace tandem

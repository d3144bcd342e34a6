#pragma once
// The batch scripts of a sweep on a Slurm cluster (tandem bench --slurm). The sweep is a job
// array: task K of N runs `tandem bench EXPERIMENT --shard K/N` into OUT/shards/, so OUT must be
// on a file system every node reaches. A merge job, which waits for the whole array (afterany),
// runs `tandem bench EXPERIMENT --merge --slurm`: it merges the shards, writes the report and the
// OMPL log and, while retries are left, submits again the shards that have runs missing (a task
// that failed or ran out of time; its finished runs are kept), with another merge job after them.
//
// This file only writes the scripts' text; the command line submits them with sbatch.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace tandem {

struct SlurmSweep {
  std::string name;                      ///< the experiment's name (for the job names)
  std::filesystem::path tandem;          ///< absolute path of the tandem binary
  std::filesystem::path experiment;      ///< absolute path of the experiment file
  std::filesystem::path out_dir;         ///< absolute; on a shared file system
  std::vector<std::string> bench_args;   ///< given to every task as well (--seeds, --allow-dir)
  unsigned tasks = 1;                    ///< shards of the sweep
  unsigned cpus_per_task = 1;            ///< each task runs this many runs at a time
  std::string partition;                 ///< "" for the cluster's default
  std::vector<std::string> sbatch_args;  ///< more #SBATCH options ("--time=2:00:00")
  unsigned retries = 1;                  ///< rounds of re-submission of failed shards
};

/// The script of the job array for these shards (1-based, ascending).
std::string array_script(const SlurmSweep& sweep, const std::vector<unsigned>& shards);
/// The script of the merge job; it re-submits with `retries_left` rounds left.
std::string merge_script(const SlurmSweep& sweep, unsigned retries_left);
/// Slurm's --array value: "1-4", "2,5,7-9".
std::string array_spec(const std::vector<unsigned>& shards);
/// A word quoted for bash (it's -> 'it'\''s'), read back unchanged.
std::string shell_quote(std::string_view word);
/// The job id in sbatch --parsable's answer ("1234" or "1234;cluster"); "" if there is none.
std::string parsable_job_id(std::string_view answer);

}  // namespace tandem

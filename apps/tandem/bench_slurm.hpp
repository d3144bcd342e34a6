#pragma once
// tandem bench --slurm: submits the shards of an experiment that have runs missing as a Slurm job
// array, and a merge job after it (tandem/experiments/slurm_scripts.hpp says what they run).

#include <ostream>
#include <string>
#include <vector>

#include "tandem/experiments/slurm_scripts.hpp"

namespace tandem::cli {

/// Writes OUT/slurm/array.sbatch and OUT/slurm/merge.sbatch and submits them with sbatch, the
/// merge job with --dependency=afterany on the array. Tells `out` the job ids and what to type
/// next. Throws InputError naming --slurm when sbatch is missing or refuses a job.
void submit_sweep(const SlurmSweep& sweep, const std::vector<unsigned>& shards,
                  unsigned retries_left, std::ostream& out);

/// Checks what a batch script cannot hold (a line break in an option, a blank in the folder's
/// path); throws InputError naming the option.
void check_slurm_sweep(const SlurmSweep& sweep);

}  // namespace tandem::cli

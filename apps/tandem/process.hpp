#pragma once
// Running another program and reading what it prints (sbatch, for tandem bench --slurm).

#include <string>
#include <vector>

namespace tandem::cli {

struct ProcessResult {
  int exit_code = -1;  ///< -1 if the program could not be started or was killed
  bool found = true;   ///< false if the program is not on PATH
  std::string output;  ///< what it wrote on stdout and stderr
};

/// Runs argv[0] (searched on PATH) with no input, waits for it and returns its output.
ProcessResult run_process(const std::vector<std::string>& argv);

}  // namespace tandem::cli

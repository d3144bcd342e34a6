#pragma once
// An experiment run as `tandem bench` runs it, for the command line and the Python module: the
// experiment file and its problem loaded, the runs (or one shard of them) run resumably, the
// shards merged, and the products written (OUT/ompl.log, OUT/report.md and its plots).

#include <atomic>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "tandem/experiments/bench_runner.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/experiments/report.hpp"
#include "tandem/scene/problem.hpp"

namespace tandem::cli {

struct BenchRequest {
  std::string experiment;  ///< the experiment file
  std::vector<std::string> allowed_dirs;
  std::string out;    ///< "" for bench-results/NAME
  unsigned jobs = 0;  ///< 0: one per core
  std::optional<std::uint64_t> seeds;
  std::optional<Shard> shard;
  std::ostream* progress = nullptr;
  bool live_progress = false;
  const std::atomic<bool>* stop = nullptr;
};

/// The experiment and its problem, and where its results go.
struct LoadedBench {
  Experiment experiment;
  Problem problem;
  std::filesystem::path out_dir;
};

/// Throws InputError for a bad experiment file or problem.
LoadedBench load_bench(const BenchRequest& request);

/// Runs what is missing (of the shard, if one is given) and returns the runs.
BenchResult run_bench_runs(const LoadedBench& bench, const BenchRequest& request);

/// Writes OUT/ompl.log and the report of these runs; `command` is quoted in the report.
ReportFiles write_bench_products(const LoadedBench& bench, const std::vector<RunRecord>& records,
                                 const std::string& command);

/// `tandem bench EXPERIMENT [--seeds S]`, as the report quotes it.
std::string bench_command_text(const BenchRequest& request);

}  // namespace tandem::cli

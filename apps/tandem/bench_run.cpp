#include "bench_run.hpp"

#include <unistd.h>

#include <ctime>
#include <fstream>
#include <thread>

#include "cli_support.hpp"
#include "tandem/core/text.hpp"
#include "tandem/experiments/ompl_log.hpp"

namespace tandem::cli {
namespace {

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0)
    return "unknown";
  return buf;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      return trim(line.substr(colon + 1)) + " x " +
             std::to_string(std::thread::hardware_concurrency()) + "\n";
    }
  }
  return "";
}

std::string now_text() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", std::gmtime(&t));
  return buf;
}

}  // namespace

LoadedBench load_bench(const BenchRequest& request) {
  Experiment experiment = load_experiment(request.experiment);
  ProblemArgs problem_args;
  problem_args.allowed_dirs = request.allowed_dirs;
  // A problem file relative to the experiment file, else a built-in scene's name.
  const std::filesystem::path relative = experiment.base_dir / experiment.problem;
  problem_args.problem = std::filesystem::exists(relative) ? relative.string() : experiment.problem;
  Problem problem = load_problem(problem_args);
  std::filesystem::path out_dir = request.out.empty()
                                      ? std::filesystem::path("bench-results") / experiment.name
                                      : std::filesystem::path(request.out);
  return {std::move(experiment), std::move(problem), std::move(out_dir)};
}

BenchResult run_bench_runs(const LoadedBench& bench, const BenchRequest& request) {
  BenchOptions options;
  options.out_dir = bench.out_dir;
  options.jobs =
      request.jobs != 0 ? request.jobs : std::max(1u, std::thread::hardware_concurrency());
  options.seeds = request.seeds;
  options.stop = request.stop;
  options.progress = request.progress;
  options.live_progress = request.live_progress;
  options.shard = request.shard;
  return run_experiment(bench.experiment, bench.problem, options);
}

ReportFiles write_bench_products(const LoadedBench& bench, const std::vector<RunRecord>& records,
                                 const std::string& command) {
  OmplLogHeader header;
  header.version = TANDEM_VERSION;
  header.hostname = host_name();
  header.date = now_text();
  header.cpuinfo = cpu_model();
  for (const RunRecord& r : records)
    header.total_time_s += r.time_s;
  write_file_atomically(bench.out_dir / "ompl.log",
                        format_ompl_log(bench.experiment, bench.problem, records, header));
  return write_report(bench.experiment, bench.problem, records, bench.out_dir, command);
}

std::string bench_command_text(const BenchRequest& request) {
  std::string command = "tandem bench " + request.experiment;
  if (request.seeds)
    command += " --seeds " + std::to_string(*request.seeds);
  return command;
}

}  // namespace tandem::cli

// tandem bench: run an experiment file (sweeps x seeds), resumably, on every core; write the runs
// (JSON lines), OMPL's benchmark log and a report with tables and plots.

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <ctime>
#include <fstream>
#include <iostream>
#include <thread>

#include "cli_support.hpp"
#include "commands.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/experiments/bench_runner.hpp"
#include "tandem/experiments/experiment.hpp"
#include "tandem/experiments/ompl_log.hpp"
#include "tandem/experiments/report.hpp"

namespace tandem::cli {
namespace {

struct BenchArgs {
  std::string experiment;
  std::vector<std::string> allowed_dirs;
  std::string out;
  unsigned jobs = 0;
  std::optional<std::uint64_t> seeds;
  bool report_only = false;
  bool quiet = false;
};

std::atomic<bool> g_stop{false};

extern "C" void on_interrupt(int) {
  g_stop.store(true);
}

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

Problem experiment_problem(const BenchArgs& args, const Experiment& experiment) {
  ProblemArgs problem_args;
  problem_args.allowed_dirs = args.allowed_dirs;
  // A problem file relative to the experiment file, else a built-in scene's name.
  const std::filesystem::path relative = experiment.base_dir / experiment.problem;
  problem_args.problem = std::filesystem::exists(relative) ? relative.string() : experiment.problem;
  return load_problem(problem_args);
}

/// --report-only: the experiment's runs already recorded.
BenchResult recorded_runs(const BenchArgs& args, const Experiment& experiment,
                          const BenchOptions& options) {
  const auto file = options.out_dir / "runs.jsonl";
  if (!std::filesystem::exists(file))
    throw InputError(file.string(), "does not exist: run the experiment first");
  const std::vector<RunRecord> all = read_records(file);
  const std::uint64_t seeds = args.seeds.value_or(experiment.seeds);
  BenchResult result;
  for (const RunConfig& c : experiment.configs) {
    for (const RunRecord& r : all) {
      if (r.config == c.label() && r.seed >= experiment.seed_start &&
          r.seed < experiment.seed_start + seeds)
        result.records.push_back(r);
    }
  }
  return result;
}

BenchResult run_runs(const BenchArgs& args, const Experiment& experiment, const Problem& problem,
                     const BenchOptions& options) {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  if (!args.quiet) {
    std::cerr << "tandem bench: " << experiment.name << " on " << problem.name << ", "
              << experiment.configs.size() << " configurations x "
              << args.seeds.value_or(experiment.seeds) << " seeds, "
              << (experiment.clock == "wall" ? std::string("in human time (one run at a time)")
                                             : std::to_string(options.jobs) + " workers")
              << ", " << experiment.time_limit << " s per run; results in "
              << options.out_dir.string() << '\n';
  }
  BenchResult result = run_experiment(experiment, problem, options);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  return result;
}

int summarise(const BenchArgs& args, const Experiment& experiment, const BenchResult& result,
              const std::filesystem::path& out_dir, const ReportFiles& report) {
  std::size_t solved = 0, valid = 0;
  for (const RunRecord& r : result.records) {
    solved += r.solved ? 1 : 0;
    valid += r.path_valid ? 1 : 0;
  }
  std::cout << experiment.name << ": " << result.records.size() << " runs recorded";
  if (!args.report_only)
    std::cout << " (" << result.ran << " now, " << result.resumed << " before)";
  std::cout << ", " << solved << " solved, " << valid << " solutions valid\n"
            << "runs: " << (out_dir / "runs.jsonl").string() << "\n"
            << "OMPL benchmark log: " << (out_dir / "ompl.log").string()
            << " (ompl_benchmark_statistics ompl.log -d results.db, then Planner Arena)\n"
            << "report: " << report.markdown.string() << '\n';
  if (result.interrupted) {
    std::cout << "interrupted: run the same command again to resume\n";
    return 130;
  }
  return valid == solved ? 0 : 1;
}

int run_bench(const BenchArgs& args) {
  const Experiment experiment = load_experiment(args.experiment);
  const Problem problem = experiment_problem(args, experiment);
  BenchOptions options;
  options.out_dir = args.out.empty() ? std::filesystem::path("bench-results") / experiment.name
                                     : std::filesystem::path(args.out);
  options.jobs = args.jobs != 0 ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
  options.seeds = args.seeds;
  options.stop = &g_stop;
  options.progress = args.quiet ? nullptr : &std::cerr;
  options.live_progress = isatty(STDERR_FILENO) != 0;
  std::string command = "tandem bench " + args.experiment;
  if (args.seeds)
    command += " --seeds " + std::to_string(*args.seeds);

  const BenchResult result = args.report_only ? recorded_runs(args, experiment, options)
                                              : run_runs(args, experiment, problem, options);
  OmplLogHeader header;
  header.version = TANDEM_VERSION;
  header.hostname = host_name();
  header.date = now_text();
  header.cpuinfo = cpu_model();
  for (const RunRecord& r : result.records)
    header.total_time_s += r.time_s;
  write_file_atomically(options.out_dir / "ompl.log",
                        format_ompl_log(experiment, problem, result.records, header));
  const ReportFiles report =
      write_report(experiment, problem, result.records, options.out_dir, command);
  return summarise(args, experiment, result, options.out_dir, report);
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  app.add_option("EXPERIMENT", args->experiment, "An experiment file (.toml); see experiments/")
      ->required();
  app.add_option("--out", args->out, "Results folder (default bench-results/NAME)");
  app.add_option("--jobs", args->jobs, "Runs at a time (default: one per core; in human time, one)")
      ->check(CLI::Range(1u, 256u));
  app.add_option("--seeds", args->seeds, "Seeds per configuration instead of the file's")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100000}));
  app.add_option(
      "--allow-dir", args->allowed_dirs,
      "A folder the problem may read meshes and URDFs from, besides its own (repeatable)");
  app.add_flag("--report-only", args->report_only,
               "Rewrite the log and report from the recorded runs");
  app.add_flag("--quiet", args->quiet, "No progress bar");
  app.footer(
      "Runs every configuration of the experiment's sweeps with every seed; each run ends in one "
      "line "
      "of\nOUT/runs.jsonl. Runs already there are not run again: after Ctrl-C or a kill, the same "
      "command\nresumes. Then writes OUT/ompl.log (OMPL's benchmark log format) and OUT/report.md "
      "with SVG plots.\nExit 0 when done and every solution passed check-path; 1 if one did not; 2 "
      "for bad input;\n130 when interrupted.");
  return [args] { return run_bench(*args); };
}

}  // namespace tandem::cli

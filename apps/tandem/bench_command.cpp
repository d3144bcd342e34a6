// tandem bench: run an experiment file (sweeps x seeds), resumably, on every core, or as shards
// (--shard K/N) on other machines or a Slurm cluster (--slurm); write the runs (JSON lines), OMPL's
// benchmark log and a report with tables and plots.

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <thread>

#include "bench_run.hpp"
#include "bench_slurm.hpp"
#include "commands.hpp"
#include "tandem/core/error.hpp"
#include "tandem/experiments/merge_shards.hpp"
#include "tandem/experiments/runs_folder.hpp"

namespace tandem::cli {
namespace {

struct BenchArgs {
  BenchRequest request;
  std::string shard;
  bool report_only = false;
  bool merge = false;
  bool quiet = false;
  bool slurm = false;
  std::string partition;
  unsigned tasks = 0;
  unsigned cpus_per_task = 0;
  std::vector<std::string> sbatch;
  unsigned retries = 1;
};

constexpr unsigned kDefaultTasks = 20;

std::atomic<bool> g_stop{false};

extern "C" void on_interrupt(int) {
  g_stop.store(true);
}

std::uint64_t seeds(const BenchArgs& args, const Experiment& experiment) {
  return args.request.seeds.value_or(experiment.seeds);
}

/// --report-only: the experiment's runs already recorded.
std::vector<RunRecord> recorded_runs(const BenchArgs& args, const LoadedBench& bench) {
  const auto file = bench.out_dir / kRunsFile;
  if (!std::filesystem::exists(file))
    throw InputError(file.string(), "does not exist: run the experiment first");
  std::map<std::string, RunRecord> done;
  index_records(load_runs_file(file, bench.problem, bench.experiment, false, nullptr), done);
  return ordered_records(bench.experiment, seeds(args, bench.experiment), done);
}

/// The summary lines and the exit code: 0 when every planned run is recorded and every solution
/// is valid, 1 otherwise.
int summarise(const BenchArgs& args, const LoadedBench& bench,
              const std::vector<RunRecord>& records, const std::string& counts,
              const ReportFiles& report) {
  std::size_t solved = 0, valid = 0;
  for (const RunRecord& r : records) {
    solved += r.solved ? 1 : 0;
    valid += r.path_valid ? 1 : 0;
  }
  const std::size_t planned = bench.experiment.configs.size() * seeds(args, bench.experiment);
  std::cout << bench.experiment.name << ": " << records.size() << " runs recorded" << counts << ", "
            << solved << " solved, " << valid << " solutions valid\n"
            << "runs: " << (bench.out_dir / kRunsFile).string() << "\n"
            << "OMPL benchmark log: " << (bench.out_dir / "ompl.log").string()
            << " (ompl_benchmark_statistics ompl.log -d results.db, then Planner Arena)\n"
            << "report: " << report.markdown.string() << '\n';
  if (records.size() < planned)
    std::cout << planned - records.size() << " of " << planned << " runs are missing\n";
  return valid == solved && records.size() >= planned ? 0 : 1;
}

/// Runs the experiment (or one shard of it) here.
int run_here(BenchArgs& args, const LoadedBench& bench) {
  BenchRequest& request = args.request;
  if (!args.shard.empty())
    request.shard = parse_shard(args.shard, "--shard");
  request.stop = &g_stop;
  request.progress = args.quiet ? nullptr : &std::cerr;
  request.live_progress = isatty(STDERR_FILENO) != 0;
  if (!args.quiet) {
    std::cerr << "tandem bench: " << bench.experiment.name << " on " << bench.problem.name << ", "
              << bench.experiment.configs.size() << " configurations x "
              << seeds(args, bench.experiment) << " seeds"
              << (request.shard ? ", shard " + args.shard : std::string()) << "; results in "
              << bench.out_dir.string() << '\n';
  }
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  const BenchResult result = run_bench_runs(bench, request);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (result.interrupted) {
    std::cout << "interrupted after " << result.ran
              << " runs: run the same command again to resume\n";
    return 130;
  }
  const std::string counts =
      " (" + std::to_string(result.ran) + " now, " + std::to_string(result.resumed) + " before)";
  if (request.shard) {
    std::cout << bench.experiment.name << " shard " << args.shard << ": " << result.records.size()
              << " of " << result.planned << " runs recorded" << counts << " in "
              << shard_file(bench.out_dir, *request.shard).string()
              << "\nwhen every shard is done: tandem bench " << request.experiment << " --out "
              << bench.out_dir.string() << " --merge\n";
    return result.records.size() == result.planned ? 0 : 1;
  }
  const ReportFiles report =
      write_bench_products(bench, result.records, bench_command_text(request));
  return summarise(args, bench, result.records, counts, report);
}

/// The sweep as Slurm jobs run it: absolute paths, and the options every task needs.
SlurmSweep slurm_sweep(const BenchArgs& args, const LoadedBench& bench) {
  SlurmSweep s;
  s.name = bench.experiment.name;
  s.tandem = std::filesystem::read_symlink("/proc/self/exe");
  s.experiment = std::filesystem::absolute(args.request.experiment).lexically_normal();
  s.out_dir = std::filesystem::absolute(bench.out_dir).lexically_normal();
  if (args.request.seeds)
    s.bench_args = {"--seeds", std::to_string(*args.request.seeds)};
  for (const std::string& d : args.request.allowed_dirs) {
    s.bench_args.push_back("--allow-dir");
    s.bench_args.push_back(std::filesystem::absolute(d).lexically_normal().string());
  }
  const std::size_t runs = bench.experiment.configs.size() * seeds(args, bench.experiment);
  s.tasks = args.tasks != 0 ? args.tasks
                            : static_cast<unsigned>(std::min<std::size_t>(kDefaultTasks, runs));
  s.cpus_per_task =
      args.cpus_per_task != 0 ? args.cpus_per_task : (bench.experiment.clock == "wall" ? 2u : 1u);
  s.partition = args.partition;
  s.sbatch_args = args.sbatch;
  s.retries = args.retries;
  check_slurm_sweep(s);
  return s;
}

/// --merge, and --slurm: merges what the shards recorded; with --slurm, submits the shards that
/// have runs missing (while retries are left), else writes the report.
int merge_or_submit(const BenchArgs& args, const LoadedBench& bench) {
  std::optional<SlurmSweep> sweep;
  if (args.slurm)
    sweep = slurm_sweep(args, bench);
  if (!args.merge) {
    std::error_code ec;
    std::filesystem::create_directories(bench.out_dir, ec);
  }
  const MergeResult merged =
      merge_shards(bench.experiment, bench.problem, bench.out_dir, seeds(args, bench.experiment),
                   sweep ? sweep->tasks : args.tasks, &std::cerr);
  const bool resubmit = args.merge ? args.retries > 0 : true;
  if (sweep && !merged.incomplete.empty() && resubmit) {
    if (args.merge)
      std::cout << "shards with runs missing: " << array_spec(merged.incomplete) << " of "
                << sweep->tasks << '\n';
    submit_sweep(*sweep, merged.incomplete, args.merge ? args.retries - 1 : args.retries,
                 std::cout);
    return 0;
  }
  const ReportFiles report =
      write_bench_products(bench, merged.records, bench_command_text(args.request));
  const std::string counts = " (from " + std::to_string(merged.shard_files) + " shard files)";
  const int code = summarise(args, bench, merged.records, counts, report);
  if (!merged.incomplete.empty()) {
    std::cout << "shards with runs missing: " << array_spec(merged.incomplete) << " of "
              << (sweep ? sweep->tasks : args.tasks) << " (run them again with --shard K/N)\n";
  }
  return code;
}

int run_bench(BenchArgs& args) {
  const LoadedBench bench = load_bench(args.request);
  if (args.report_only) {
    const std::vector<RunRecord> records = recorded_runs(args, bench);
    const ReportFiles report =
        write_bench_products(bench, records, bench_command_text(args.request));
    return summarise(args, bench, records, "", report);
  }
  if (args.merge || args.slurm)
    return merge_or_submit(args, bench);
  return run_here(args, bench);
}

void add_slurm_options(CLI::App& app, BenchArgs& args) {
  auto* slurm = app.add_flag("--slurm", args.slurm,
                             "Submit the runs as a Slurm job array and a merge job (sbatch)");
  app.add_option("--partition", args.partition, "Slurm partition (default: the cluster's)")
      ->needs(slurm);
  app.add_option("--tasks", args.tasks,
                 "Shards of the sweep: array tasks with --slurm (default min(runs, 20))")
      ->check(CLI::Range(1u, 1000u));
  app.add_option("--cpus-per-task", args.cpus_per_task,
                 "CPUs of each task, runs at a time (default 1; in human time 2)")
      ->check(CLI::Range(1u, 256u))
      ->needs(slurm);
  app.add_option("--sbatch", args.sbatch, "Another sbatch option, e.g. --time=2:00:00 (repeatable)")
      ->needs(slurm);
  app.add_option("--retries", args.retries,
                 "Rounds of re-submitting shards with runs missing (default 1)")
      ->check(CLI::Range(0u, 100u))
      ->needs(slurm);
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  BenchRequest& r = args->request;
  app.add_option("EXPERIMENT", r.experiment, "An experiment file (.toml); see experiments/")
      ->required();
  app.add_option("--out", r.out, "Results folder (default bench-results/NAME)");
  app.add_option("--jobs", r.jobs, "Runs at a time (default: one per core; in human time, one)")
      ->check(CLI::Range(1u, 256u));
  app.add_option("--seeds", r.seeds, "Seeds per configuration instead of the file's")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{100000}));
  app.add_option(
      "--allow-dir", r.allowed_dirs,
      "A folder the problem may read meshes and URDFs from, besides its own (repeatable)");
  auto* report = app.add_flag("--report-only", args->report_only,
                              "Rewrite the log and report from the recorded runs");
  auto* shard = app.add_option("--shard", args->shard,
                               "Run only shard K of N of the runs, into OUT/shards/ (K/N)");
  auto* merge = app.add_flag("--merge", args->merge,
                             "Merge OUT/shards/ into OUT/runs.jsonl, then write log and report");
  add_slurm_options(app, *args);
  shard->excludes(report)->excludes(merge)->excludes("--slurm");
  merge->excludes(report);
  report->excludes("--slurm");
  app.add_flag("--quiet", args->quiet, "No progress bar");
  app.footer(
      "Runs every configuration of the experiment's sweeps with every seed; each run ends in one "
      "line\nof OUT/runs.jsonl. Runs already there are not run again: after Ctrl-C or a kill, the "
      "same\ncommand resumes. Then writes OUT/ompl.log (OMPL's benchmark log format) and "
      "OUT/report.md\nwith SVG plots.\n\nOn several machines: --shard K/N runs the K-th of N "
      "shares into OUT/shards/, and --merge\nputs them together and writes the report. On a Slurm "
      "cluster (OUT on a shared file system):\n--slurm submits the shards with runs missing as a "
      "job array and a merge job that re-submits\nfailed shards (--retries) and writes the report; "
      "the same command submits what is still missing.\n\nExit 0 when done and every solution "
      "passed check-path; 1 if one did not or runs are missing;\n2 for bad input; 130 when "
      "interrupted.");
  return [args] { return run_bench(*args); };
}

}  // namespace tandem::cli

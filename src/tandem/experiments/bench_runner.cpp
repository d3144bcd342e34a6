#include "tandem/experiments/bench_runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/core/text.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/runs/wall_run.hpp"

namespace tandem {
namespace {

/// The cores a live session uses (the operator's thread and the planner's), which a run in human
/// time gets, and a planner alone with it.
constexpr unsigned kHumanTimeCores = 2;

std::string duration_text(double s) {
  if (!std::isfinite(s) || s < 0.0)
    return "?";
  const auto total = static_cast<long long>(s + 0.5);
  char buf[32];
  if (total >= 3600) {
    std::snprintf(buf, sizeof buf, "%lldh%02lldm", total / 3600, (total / 60) % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%lldm%02llds", total / 60, total % 60);
  }
  return buf;
}

struct Job {
  std::size_t config = 0;
  std::uint64_t seed = 0;
};

/// Shared by the workers: the next job, the file, the progress line.
class Recorder {
 public:
  Recorder(const std::filesystem::path& file, const BenchOptions& options, std::size_t total,
           std::size_t done)
      : file_(file), out_(file, std::ios::app), options_(options), total_(total), done_(done) {
    if (!out_)
      throw InputError(file.string(), "cannot be opened for appending");
  }

  void record(const RunRecord& r) {
    const std::lock_guard lock(mutex_);
    out_ << format_record(r) << '\n';
    out_.flush();
    if (!out_)
      throw InputError(file_.string(), "could not be written (disk full?)");
    records_.push_back(r);
    ++done_;
    ++ran_;
    solved_ += r.solved ? 1 : 0;
    draw(false);
  }

  void draw(bool final) {
    if (options_.progress == nullptr)
      return;
    const double elapsed = watch_.seconds();
    const std::size_t left = total_ - done_;
    const double eta =
        ran_ == 0 ? std::nan("") : elapsed / static_cast<double>(ran_) * static_cast<double>(left);
    constexpr int kWidth = 30;
    const int filled =
        total_ == 0
            ? kWidth
            : static_cast<int>(kWidth * static_cast<double>(done_) / static_cast<double>(total_));
    std::ostringstream line;
    line << '[' << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kWidth - filled), '.') << "] " << done_ << '/'
         << total_ << " runs, " << solved_ << " of " << ran_ << " new solved, elapsed "
         << duration_text(elapsed) << ", left " << (left == 0 ? "0m00s" : duration_text(eta));
    if (options_.live_progress) {
      *options_.progress << '\r' << line.str() << "   " << (final ? "\n" : "") << std::flush;
    } else {
      // A log, not a terminal: a line at every tenth of the runs and at the end.
      const std::size_t step = std::max<std::size_t>(1, total_ / 10);
      if ((final || done_ % step == 0) && done_ != printed_) {
        *options_.progress << line.str() << '\n' << std::flush;
        printed_ = done_;
      }
    }
  }

  std::vector<RunRecord> take() { return std::move(records_); }
  std::size_t ran() const { return ran_; }

 private:
  std::filesystem::path file_;
  std::ofstream out_;
  const BenchOptions& options_;
  std::size_t total_;
  std::size_t done_;
  std::size_t ran_ = 0;
  std::size_t solved_ = 0;
  std::size_t printed_ = SIZE_MAX;
  std::vector<RunRecord> records_;
  std::mutex mutex_;
  Stopwatch watch_;
};

/// Where the runs of this invocation go: OUT/runs.jsonl, or the shard's file.
std::filesystem::path runs_file(const BenchOptions& options) {
  return options.shard ? shard_file(options.out_dir, *options.shard) : options.out_dir / kRunsFile;
}

OperatorClock operator_clock(const Experiment& experiment) {
  return experiment.clock == "wall" ? OperatorClock::seconds : OperatorClock::ticks;
}

/// Every configuration must be runnable before any run starts (an unknown operator, a missing
/// guide or trace): an error now, not after an hour.
void check_runnable(const Experiment& experiment, const Problem& problem) {
  for (const RunConfig& c : experiment.configs) {
    const RunSpec spec = c.spec(experiment.seed_start, experiment.time_limit, problem.hints);
    if (uses_operator(spec)) {
      try {
        (void)make_operator(problem, spec, operator_clock(experiment));
      } catch (const InputError& e) {
        throw InputError(experiment.name, "configuration " + c.label() + ": " + e.what());
      }
    }
  }
}

/// Creates the output folder (and its shards folder) and reads the runs already done: those of
/// OUT/runs.jsonl and, for a shard, those of its own file.
std::map<std::string, RunRecord> open_output(const Experiment& experiment, const Problem& problem,
                                             const BenchOptions& options) {
  const std::filesystem::path& out_dir = options.out_dir;
  const std::filesystem::path file = runs_file(options);
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec || !std::filesystem::is_directory(file.parent_path()))
    throw InputError(file.parent_path().string(), "cannot be created as a folder");
  std::map<std::string, RunRecord> done;
  // A shard only reads the whole experiment's file, which other shards may read at the same time.
  index_records(
      load_runs_file(out_dir / kRunsFile, problem, experiment, !options.shard, options.progress),
      done);
  if (options.shard)
    index_records(load_runs_file(file, problem, experiment, true, options.progress), done);
  return done;
}

/// The runs not done yet, seed-major: an interrupted experiment has every configuration for its
/// first seeds. Counts the planned and the resumed runs into `result` (a shard's only).
std::vector<Job> plan_jobs(const std::vector<PlannedRun>& runs, const BenchOptions& options,
                           const std::map<std::string, RunRecord>& done, BenchResult& result) {
  std::vector<Job> jobs;
  for (std::size_t p = 0; p < runs.size(); ++p) {
    if (options.shard && shard_of(p, options.shard->count) != options.shard->index)
      continue;
    ++result.planned;
    if (done.count(runs[p].key) != 0) {
      ++result.resumed;
    } else {
      jobs.push_back({runs[p].config, runs[p].seed});
    }
  }
  return jobs;
}

/// The jobs and what the workers share: the next job, the first error, the stop flags.
///
/// Threading: work() runs on every worker thread; each owns its collision checker, motion
/// validator and planner, the problem is shared read-only and finished runs go to the Recorder.
/// The first exception stops the other workers between runs (and their planners through
/// stop_all_, unless the caller's stop flag is used) and is rethrown by rethrow() after the join.
class JobQueue {
 public:
  JobQueue(const Experiment& experiment, const Problem& problem, const BenchOptions& options,
           std::vector<Job> jobs, Recorder& recorder)
      : experiment_(experiment),
        problem_(problem),
        options_(options),
        jobs_(std::move(jobs)),
        recorder_(recorder) {}

  /// Runs the jobs on options.jobs threads (at most one a job) and waits for them.
  void run_all() {
    if (jobs_.empty())
      return;
    const unsigned jobs = experiment_.clock == "wall" ? 1u : options_.jobs;
    const unsigned n_workers =
        std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(jobs_.size())));
    std::vector<std::thread> threads;
    for (unsigned w = 0; w < n_workers; ++w)
      threads.emplace_back([this] { work(); });
    for (auto& t : threads)
      t.join();
  }

  void rethrow() const {
    if (error_)
      std::rethrow_exception(error_);
  }

 private:
  bool stopping() const {
    return failed_.load() || (options_.stop != nullptr && options_.stop->load());
  }

  void work() {
    try {
      CollisionChecker checker(problem_.scene);
      MotionValidator validator(problem_.space, checker);
      for (std::size_t i = next_++; i < jobs_.size() && !stopping(); i = next_++) {
        if (!run_one(jobs_[i], checker, validator))
          break;
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex_);
      if (!error_)
        error_ = std::current_exception();
      failed_ = true;
      stop_all_ = true;
    }
  }

  /// Runs and records one job; false when its planner was interrupted (not recorded).
  bool run_one(const Job& job, CollisionChecker& checker, MotionValidator& validator) {
    const RunConfig& config = experiment_.configs[job.config];
    const double time_limit = experiment_.time_limit;
    RunSpec spec = config.spec(job.seed, time_limit, problem_.hints);
    const bool human_time = experiment_.clock == "wall";
    // Virtual time: runs are --jobs at a time, one thread each. Human time: one run at a time
    // with both cores, the person's thread and the planner's, or two for a planner alone.
    if (spec.settings.threads == 0)
      spec.settings.threads = human_time ? kHumanTimeCores : 1;
    // The planner stops on Ctrl-C; a failure of another worker stops this one between runs.
    spec.stop = options_.stop != nullptr ? options_.stop : &stop_all_;
    const RunOutcome outcome = human_time ? execute_wall_run(problem_, spec, checker)
                                          : execute_run(problem_, spec, checker);
    if (outcome.status == PlannerStatus::interrupted)
      return false;
    // Checked the way the run's planner checked its motions.
    validator.configure(validation_settings(spec.settings));
    const bool valid = outcome.status == PlannerStatus::solved && !outcome.path.empty() &&
                       check_path(outcome.path, validator).valid;
    RunRecord record = make_record(problem_.name, config.label(), config.values, job.seed,
                                   time_limit, outcome, valid);
    record.clock = experiment_.clock;
    recorder_.record(record);
    return true;
  }

  const Experiment& experiment_;
  const Problem& problem_;
  const BenchOptions& options_;
  const std::vector<Job> jobs_;
  Recorder& recorder_;
  std::atomic<std::size_t> next_{0};
  std::mutex error_mutex_;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
  std::atomic<bool> stop_all_{false};
};

}  // namespace

std::vector<RunRecord> read_records(const std::filesystem::path& runs_file) {
  std::vector<RunRecord> records;
  std::ifstream in(runs_file);
  if (!in)
    throw InputError(runs_file.string(), "cannot be read");
  std::string line;
  while (std::getline(in, line)) {
    if (auto r = parse_record(line))
      records.push_back(std::move(*r));
  }
  return records;
}

BenchResult run_experiment(const Experiment& experiment, const Problem& problem,
                           const BenchOptions& options) {
  const Stopwatch wall;
  const std::uint64_t seeds = options.seeds.value_or(experiment.seeds);
  check_runnable(experiment, problem);
  const std::filesystem::path file = runs_file(options);
  std::map<std::string, RunRecord> done = open_output(experiment, problem, options);

  BenchResult result;
  const std::vector<PlannedRun> runs = planned_runs(experiment, seeds);
  std::vector<Job> jobs = plan_jobs(runs, options, done, result);
  Recorder recorder(file, options, result.planned, result.resumed);
  if (options.progress != nullptr && result.resumed > 0) {
    *options.progress << file.string() << ": " << result.resumed << " of " << result.planned
                      << " runs already done; running the other " << jobs.size() << '\n';
  }
  JobQueue queue(experiment, problem, options, std::move(jobs), recorder);
  queue.run_all();
  recorder.draw(true);
  queue.rethrow();

  result.ran = recorder.ran();
  result.interrupted = options.stop != nullptr && options.stop->load();
  index_records(recorder.take(), done);
  if (options.shard) {
    // A shard's result is its own runs.
    for (std::size_t p = 0; p < runs.size(); ++p) {
      if (shard_of(p, options.shard->count) != options.shard->index)
        done.erase(runs[p].key);
    }
  }
  result.records = ordered_records(experiment, seeds, done);
  result.wall_s = wall.seconds();
  return result;
}

}  // namespace tandem

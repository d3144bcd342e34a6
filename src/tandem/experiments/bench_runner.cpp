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
#include "tandem/io/text.hpp"
#include "tandem/planning/path.hpp"

namespace tandem {
namespace {

constexpr const char* kRunsFile = "runs.jsonl";

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

RunRecord make_record(const Problem& problem, const RunConfig& config, std::uint64_t seed,
                      double time_limit, const RunOutcome& outcome, bool path_valid) {
  RunRecord r;
  r.problem = problem.name;
  r.config = config.label();
  for (const auto& [k, v] : config.values)
    r.params[k] = format_param(v);
  r.seed = seed;
  r.time_limit_s = time_limit;
  r.status = std::string(to_string(outcome.status));
  r.solved = outcome.status == PlannerStatus::solved;
  r.path_valid = path_valid;
  const PlannerStats& s = outcome.stats;
  r.time_s = s.time_s;
  r.iterations = s.iterations;
  r.nodes = s.nodes;
  r.edges = s.edges;
  r.collision_checks = s.collision_checks;
  r.nodes_by_source = s.nodes_by_source;
  r.path_length = outcome.path_length;
  r.operator_iterations = s.operator_iterations;
  r.contact_entries = s.contact_entries;
  r.operator_waits = outcome.operator_waits;
  r.tree_digest = format_digest(outcome.tree_digest);
  return r;
}

/// Keeps the complete lines of a runs file and rewrites it without a torn last line, so that
/// appending goes on from a clean end.
std::vector<RunRecord> load_and_repair(const std::filesystem::path& file, std::ostream* log) {
  std::vector<RunRecord> records;
  if (!std::filesystem::exists(file))
    return records;
  std::ifstream in(file);
  if (!in)
    throw InputError(file.string(), "cannot be read");
  std::string line;
  std::size_t bad = 0;
  std::ostringstream kept;
  while (std::getline(in, line)) {
    if (line.empty())
      continue;
    if (auto r = parse_record(line)) {
      records.push_back(std::move(*r));
      kept << line << '\n';
    } else {
      ++bad;
    }
  }
  if (bad > 0) {
    write_file_atomically(file, kept.str());
    if (log != nullptr) {
      *log << file.string() << ": dropped " << bad
           << " incomplete line(s) (a run cut short); they will run again\n";
    }
  }
  return records;
}

}  // namespace

std::string RunRecord::param(const std::string& name) const {
  auto it = params.find(name);
  return it == params.end() ? std::string() : it->second;
}

std::string format_record(const RunRecord& r) {
  nlohmann::json j;
  j["problem"] = r.problem;
  j["config"] = r.config;
  j["params"] = r.params;
  j["seed"] = r.seed;
  j["time_limit_s"] = r.time_limit_s;
  j["status"] = r.status;
  j["solved"] = r.solved;
  j["path_valid"] = r.path_valid;
  j["time_s"] = r.time_s;
  j["iterations"] = r.iterations;
  j["nodes"] = r.nodes;
  j["edges"] = r.edges;
  j["collision_checks"] = r.collision_checks;
  nlohmann::json sources;
  for (std::size_t k = 0; k < kNodeSources; ++k)
    sources[std::string(to_string(static_cast<NodeSource>(k)))] = r.nodes_by_source[k];
  j["nodes_by_source"] = sources;
  j["path_length"] = r.path_length;
  j["operator_iterations"] = r.operator_iterations;
  j["contact_entries"] = r.contact_entries;
  j["operator_waits"] = r.operator_waits;
  j["tree_digest"] = r.tree_digest;
  return j.dump();
}

std::optional<RunRecord> parse_record(const std::string& line) {
  try {
    const nlohmann::json j = nlohmann::json::parse(line);
    RunRecord r;
    r.problem = j.at("problem").get<std::string>();
    r.config = j.at("config").get<std::string>();
    r.params = j.at("params").get<std::map<std::string, std::string>>();
    r.seed = j.at("seed").get<std::uint64_t>();
    r.time_limit_s = j.at("time_limit_s").get<double>();
    r.status = j.at("status").get<std::string>();
    r.solved = j.at("solved").get<bool>();
    r.path_valid = j.at("path_valid").get<bool>();
    r.time_s = j.at("time_s").get<double>();
    r.iterations = j.at("iterations").get<std::uint64_t>();
    r.nodes = j.at("nodes").get<std::size_t>();
    r.edges = j.at("edges").get<std::size_t>();
    r.collision_checks = j.at("collision_checks").get<std::uint64_t>();
    for (std::size_t k = 0; k < kNodeSources; ++k) {
      r.nodes_by_source[k] = j.at("nodes_by_source")
                                 .at(std::string(to_string(static_cast<NodeSource>(k))))
                                 .get<std::size_t>();
    }
    r.path_length = j.at("path_length").get<double>();
    r.operator_iterations = j.at("operator_iterations").get<std::uint64_t>();
    r.contact_entries = j.at("contact_entries").get<std::uint64_t>();
    r.operator_waits = j.value("operator_waits", std::uint64_t{0});
    r.tree_digest = j.at("tree_digest").get<std::string>();
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

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
  const double time_limit = experiment.time_limit;

  // Every configuration must be runnable before any run starts (an unknown operator, a missing
  // guide or trace): an error now, not after an hour.
  for (const RunConfig& c : experiment.configs) {
    const RunSpec spec = c.spec(experiment.seed_start, time_limit, problem.hints);
    if (is_interactive(spec.mode)) {
      try {
        (void)make_operator(problem, spec);
      } catch (const InputError& e) {
        throw InputError(experiment.name, "configuration " + c.label() + ": " + e.what());
      }
    }
  }

  std::error_code ec;
  std::filesystem::create_directories(options.out_dir, ec);
  if (ec || !std::filesystem::is_directory(options.out_dir)) {
    throw InputError(options.out_dir.string(), "cannot be created as a folder");
  }
  const std::filesystem::path runs_file = options.out_dir / kRunsFile;
  std::vector<RunRecord> previous = load_and_repair(runs_file, options.progress);
  for (const RunRecord& r : previous) {
    if (r.problem != problem.name || r.time_limit_s != time_limit) {
      std::ostringstream msg;
      msg << "holds runs of problem '" << r.problem << "' with a time limit of " << r.time_limit_s
          << " s; this experiment runs '" << problem.name << "' with " << time_limit
          << " s. Use another --out folder, or delete this one to start again";
      throw InputError(runs_file.string(), msg.str());
    }
  }

  std::map<std::string, RunRecord> done;
  for (RunRecord& r : previous) {
    std::string key = r.key();
    done.insert_or_assign(std::move(key), std::move(r));
  }
  // Seed-major order: an interrupted experiment has every configuration for its first seeds.
  std::vector<Job> jobs;
  BenchResult result;
  for (std::uint64_t s = 0; s < seeds; ++s) {
    for (std::size_t c = 0; c < experiment.configs.size(); ++c) {
      const std::uint64_t seed = experiment.seed_start + s;
      ++result.planned;
      if (done.count(experiment.configs[c].label() + " #" + std::to_string(seed)) != 0) {
        ++result.resumed;
      } else {
        jobs.push_back({c, seed});
      }
    }
  }

  Recorder recorder(runs_file, options, result.planned, result.resumed);
  if (options.progress != nullptr && result.resumed > 0) {
    *options.progress << runs_file.string() << ": " << result.resumed << " of " << result.planned
                      << " runs already done; running the other " << jobs.size() << '\n';
  }
  std::atomic<std::size_t> next{0};
  std::mutex error_mutex;
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  std::atomic<bool> stop_all{false};
  auto stopping = [&] {
    return failed.load() || (options.stop != nullptr && options.stop->load());
  };
  auto worker = [&] {
    try {
      CollisionChecker checker(problem.scene);
      MotionValidator validator(problem.space, checker);
      for (std::size_t i = next++; i < jobs.size() && !stopping(); i = next++) {
        const Job& job = jobs[i];
        const RunConfig& config = experiment.configs[job.config];
        RunSpec spec = config.spec(job.seed, time_limit, problem.hints);
        // The planner stops on Ctrl-C; a failure of another worker stops this one between runs.
        spec.stop = options.stop != nullptr ? options.stop : &stop_all;
        const RunOutcome outcome = execute_run(problem, spec, checker);
        if (outcome.status == PlannerStatus::interrupted)
          break;
        const bool valid = outcome.status == PlannerStatus::solved && !outcome.path.empty() &&
                           check_path(outcome.path, validator).valid;
        recorder.record(make_record(problem, config, job.seed, time_limit, outcome, valid));
      }
    } catch (...) {
      const std::lock_guard lock(error_mutex);
      if (!error)
        error = std::current_exception();
      failed = true;
      stop_all = true;
    }
  };
  const unsigned n_workers =
      std::max(1u, std::min<unsigned>(options.jobs, static_cast<unsigned>(jobs.size())));
  std::vector<std::thread> threads;
  if (!jobs.empty()) {
    for (unsigned w = 0; w < n_workers; ++w)
      threads.emplace_back(worker);
    for (auto& t : threads)
      t.join();
  }
  recorder.draw(true);
  if (error)
    std::rethrow_exception(error);

  result.ran = recorder.ran();
  result.interrupted = options.stop != nullptr && options.stop->load();
  for (RunRecord& r : recorder.take()) {
    std::string key = r.key();
    done.insert_or_assign(std::move(key), std::move(r));
  }
  for (const RunConfig& c : experiment.configs) {
    for (std::uint64_t s = 0; s < seeds; ++s) {
      auto it = done.find(c.label() + " #" + std::to_string(experiment.seed_start + s));
      if (it != done.end())
        result.records.push_back(it->second);
    }
  }
  result.wall_s = wall.seconds();
  return result;
}

}  // namespace tandem

#include "tandem/experiments/runs_folder.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

constexpr unsigned kMaxShards = 10000;

bool parse_count(std::string_view text, unsigned& value) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && !text.empty();
}

void check_same_experiment(const std::filesystem::path& file, const RunRecord& r,
                           const Problem& problem, const Experiment& experiment) {
  if (r.problem == problem.name && r.time_limit_s == experiment.time_limit &&
      r.clock == experiment.clock)
    return;
  std::ostringstream msg;
  msg << "holds runs of problem '" << r.problem << "' with a time limit of " << r.time_limit_s
      << " s in " << r.clock << " time; this experiment runs '" << problem.name << "' with "
      << experiment.time_limit << " s in " << experiment.clock
      << " time. Use another --out folder, or delete this one to start again";
  throw InputError(file.string(), msg.str());
}

}  // namespace

Shard parse_shard(std::string_view text, const std::string& option) {
  const auto slash = text.find('/');
  Shard s;
  if (slash == std::string_view::npos || !parse_count(text.substr(0, slash), s.index) ||
      !parse_count(text.substr(slash + 1), s.count) || s.index < 1 || s.count > kMaxShards ||
      s.index > s.count) {
    throw InputError(option, "must be K/N with 1 <= K <= N <= " + std::to_string(kMaxShards) +
                                 ", not '" + std::string(text) + "'");
  }
  return s;
}

std::filesystem::path shard_file(const std::filesystem::path& out_dir, const Shard& shard) {
  return out_dir / "shards" /
         ("shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".jsonl");
}

unsigned shard_of(std::size_t position, unsigned count) {
  return static_cast<unsigned>(position % count) + 1;
}

std::vector<PlannedRun> planned_runs(const Experiment& experiment, std::uint64_t seeds) {
  std::vector<PlannedRun> runs;
  for (std::uint64_t s = 0; s < seeds; ++s) {
    for (std::size_t c = 0; c < experiment.configs.size(); ++c) {
      const std::uint64_t seed = experiment.seed_start + s;
      runs.push_back({c, seed, experiment.configs[c].label() + " #" + std::to_string(seed)});
    }
  }
  return runs;
}

std::vector<RunRecord> load_runs_file(const std::filesystem::path& file, const Problem& problem,
                                      const Experiment& experiment, bool repair,
                                      std::ostream* log) {
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
      check_same_experiment(file, *r, problem, experiment);
      records.push_back(std::move(*r));
      kept << line << '\n';
    } else {
      ++bad;
    }
  }
  if (bad > 0 && repair) {
    write_file_atomically(file, kept.str());
    if (log != nullptr) {
      *log << file.string() << ": dropped " << bad
           << " incomplete line(s) (a run cut short); they will run again\n";
    }
  }
  return records;
}

void index_records(std::vector<RunRecord>&& records, std::map<std::string, RunRecord>& done) {
  for (RunRecord& r : records) {
    std::string key = r.key();
    done.insert_or_assign(std::move(key), std::move(r));
  }
}

std::vector<RunRecord> ordered_records(const Experiment& experiment, std::uint64_t seeds,
                                       const std::map<std::string, RunRecord>& done) {
  std::vector<RunRecord> records;
  for (const RunConfig& c : experiment.configs) {
    for (std::uint64_t s = 0; s < seeds; ++s) {
      auto it = done.find(c.label() + " #" + std::to_string(experiment.seed_start + s));
      if (it != done.end())
        records.push_back(it->second);
    }
  }
  return records;
}

}  // namespace tandem

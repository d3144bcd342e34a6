#include "tandem/experiments/merge_shards.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"

namespace tandem {
namespace {

/// OUT/shards/*.jsonl in name order (the order does not change the result: a run is in one
/// shard, and a run found twice is the same run).
std::vector<std::filesystem::path> shard_files(const std::filesystem::path& out_dir) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path dir = out_dir / "shards";
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".jsonl")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// The experiment's runs first, in report order, then any others of the folder.
std::string runs_text(const std::vector<RunRecord>& ordered,
                      const std::map<std::string, RunRecord>& done) {
  std::ostringstream text;
  std::set<std::string> written;
  for (const RunRecord& r : ordered) {
    text << format_record(r) << '\n';
    written.insert(r.key());
  }
  for (const auto& [key, r] : done) {
    if (written.count(key) == 0)
      text << format_record(r) << '\n';
  }
  return text.str();
}

std::vector<unsigned> incomplete_shards(const Experiment& experiment, std::uint64_t seeds,
                                        unsigned shards,
                                        const std::map<std::string, RunRecord>& done) {
  std::set<unsigned> missing;
  if (shards == 0)
    return {};
  const std::vector<PlannedRun> runs = planned_runs(experiment, seeds);
  for (std::size_t p = 0; p < runs.size(); ++p) {
    if (done.count(runs[p].key) == 0)
      missing.insert(shard_of(p, shards));
  }
  return {missing.begin(), missing.end()};
}

}  // namespace

MergeResult merge_shards(const Experiment& experiment, const Problem& problem,
                         const std::filesystem::path& out_dir, std::uint64_t seeds, unsigned shards,
                         std::ostream* log) {
  const std::filesystem::path runs = out_dir / kRunsFile;
  if (!std::filesystem::is_directory(out_dir))
    throw InputError(out_dir.string(), "does not exist: run the experiment (or its shards) first");
  std::map<std::string, RunRecord> done;
  index_records(load_runs_file(runs, problem, experiment, false, log), done);
  MergeResult result;
  for (const std::filesystem::path& file : shard_files(out_dir)) {
    index_records(load_runs_file(file, problem, experiment, false, log), done);
    ++result.shard_files;
  }
  result.records = ordered_records(experiment, seeds, done);
  result.planned = experiment.configs.size() * seeds;
  result.incomplete = incomplete_shards(experiment, seeds, shards, done);
  write_file_atomically(runs, runs_text(result.records, done));
  return result;
}

}  // namespace tandem

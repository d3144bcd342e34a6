// Shards of an experiment: every run in exactly one shard, shards that resume, a merge that gives
// the runs of one whole run, and the Slurm batch scripts that run them.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "support/runs.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/experiments/bench_runner.hpp"
#include "tandem/experiments/merge_shards.hpp"
#include "tandem/experiments/runs_folder.hpp"
#include "tandem/experiments/slurm_scripts.hpp"

namespace tandem {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(Shards, ParseKOfNAndRejectEverythingElse) {
  const Shard s = parse_shard("3/8", "--shard");
  EXPECT_EQ(s.index, 3u);
  EXPECT_EQ(s.count, 8u);
  for (const char* bad : {"0/4", "5/4", "4", "1/", "/2", "a/b", "1/2/3", "-1/2", "1/10001", ""}) {
    try {
      (void)parse_shard(bad, "--shard");
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("--shard")) << bad;
    }
  }
  EXPECT_EQ(shard_file("out", {2, 5}), std::filesystem::path("out/shards/shard-2-of-5.jsonl"));
}

TEST(Shards, DealEveryRunToOneShardAndEveryConfigurationToEachShard) {
  test::ExperimentFixture f;
  const std::vector<PlannedRun> runs = planned_runs(f.experiment, 3);
  ASSERT_EQ(runs.size(), 6u);
  // Seed-major: both configurations of the first seed first.
  EXPECT_EQ(runs[0].seed, 1u);
  EXPECT_EQ(runs[1].seed, 1u);
  EXPECT_NE(runs[0].config, runs[1].config);
  std::vector<unsigned> shards;
  for (std::size_t p = 0; p < runs.size(); ++p)
    shards.push_back(shard_of(p, 2));
  EXPECT_THAT(shards, ElementsAre(1, 2, 1, 2, 1, 2));
}

/// The runs' deterministic content, by key (timings apart).
std::map<std::string, std::string> outcomes(const std::vector<RunRecord>& records) {
  std::map<std::string, std::string> m;
  for (const RunRecord& r : records) {
    m[r.key()] = r.status + " " + std::to_string(r.nodes) + " " + r.tree_digest + " " +
                 std::to_string(r.path_valid);
  }
  return m;
}

TEST(Shards, MergedShardsGiveTheRunsOfOneWholeRun) {
  test::ExperimentFixture f;
  test::TempDir dir;
  BenchOptions whole;
  whole.out_dir = dir.path() / "whole";
  whole.jobs = 2;
  const BenchResult all = run_experiment(f.experiment, f.problem, whole);
  ASSERT_EQ(all.records.size(), 6u);

  BenchOptions part;
  part.out_dir = dir.path() / "sharded";
  part.jobs = 1;
  std::set<std::string> keys;
  for (unsigned k = 1; k <= 4; ++k) {
    part.shard = Shard{k, 4};
    const BenchResult r = run_experiment(f.experiment, f.problem, part);
    EXPECT_EQ(r.ran, r.planned);
    for (const RunRecord& rec : r.records)
      EXPECT_TRUE(keys.insert(rec.key()).second) << rec.key() << " in two shards";
    // Run again: the shard's runs are kept, nothing runs.
    EXPECT_EQ(run_experiment(f.experiment, f.problem, part).ran, 0u);
  }
  EXPECT_EQ(keys.size(), 6u);
  const MergeResult merged = merge_shards(f.experiment, f.problem, part.out_dir, 3, 4, nullptr);
  EXPECT_EQ(merged.shard_files, 4u);
  EXPECT_TRUE(merged.incomplete.empty());
  EXPECT_EQ(outcomes(merged.records), outcomes(all.records));
  // Report order, as a whole run gives it.
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(merged.records[i].key(), all.records[i].key());
  EXPECT_EQ(
      load_runs_file(part.out_dir / kRunsFile, f.problem, f.experiment, false, nullptr).size(), 6u);
}

TEST(Shards, MergeNamesTheShardsWithRunsMissingAndKeepsOtherRuns) {
  test::ExperimentFixture f;
  test::TempDir dir;
  BenchOptions part;
  part.out_dir = dir.path();
  part.shard = Shard{2, 3};
  (void)run_experiment(f.experiment, f.problem, part);
  const MergeResult merged = merge_shards(f.experiment, f.problem, dir.path(), 3, 3, nullptr);
  EXPECT_EQ(merged.records.size(), 2u);
  EXPECT_THAT(merged.incomplete, ElementsAre(1, 3));
  // With one seed, the runs of the other seeds are not the experiment's but stay in the file.
  const MergeResult one_seed = merge_shards(f.experiment, f.problem, dir.path(), 1, 3, nullptr);
  EXPECT_EQ(load_runs_file(dir.path() / kRunsFile, f.problem, f.experiment, false, nullptr).size(),
            2u);
  EXPECT_LE(one_seed.records.size(), 2u);
  EXPECT_THROW((void)merge_shards(f.experiment, f.problem, dir.path() / "none", 3, 3, nullptr),
               InputError);
}

TEST(Shards, AShardDoesNotRunWhatTheWholeFolderAlreadyHas) {
  test::ExperimentFixture f;
  test::TempDir dir;
  BenchOptions whole;
  whole.out_dir = dir.path();
  whole.seeds = 1;
  (void)run_experiment(f.experiment, f.problem, whole);
  BenchOptions part = whole;
  part.seeds = std::nullopt;
  part.shard = Shard{1, 1};
  const BenchResult r = run_experiment(f.experiment, f.problem, part);
  EXPECT_EQ(r.resumed, 2u);
  EXPECT_EQ(r.ran, 4u);
}

TEST(SlurmScripts, ArraySpecsAndQuotingThatBashReadsBack) {
  EXPECT_EQ(array_spec({1, 2, 3, 4}), "1-4");
  EXPECT_EQ(array_spec({2, 5, 7, 8, 9}), "2,5,7-9");
  EXPECT_EQ(array_spec({3}), "3");
  EXPECT_EQ(parsable_job_id("1234;cluster\n"), "1234");
  EXPECT_EQ(parsable_job_id("sbatch: error"), "");
  test::TempDir dir;
  const std::string word = "it's a $HOME `x` \"y\" \\ z";
  const auto out = dir.path() / "echo";
  const std::string command = "printf %s " + shell_quote(word) + " > " + shell_quote(out.string());
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(read_text_file(out), word);
}

TEST(SlurmScripts, TheArrayRunsItsShardAndTheMergeJobResubmits) {
  SlurmSweep sweep;
  sweep.name = "env1";
  sweep.tandem = "/opt/tandem/bin/tandem";
  sweep.experiment = "/home/a/env1.toml";
  sweep.out_dir = "/scratch/a/env1";
  sweep.bench_args = {"--seeds", "5"};
  sweep.tasks = 8;
  sweep.cpus_per_task = 2;
  sweep.partition = "short";
  sweep.sbatch_args = {"--time=1:00:00"};
  const std::string array = array_script(sweep, {2, 3, 7});
  EXPECT_THAT(array, HasSubstr("#SBATCH --array=2-3,7\n"));
  EXPECT_THAT(array, HasSubstr("#SBATCH --cpus-per-task=2\n"));
  EXPECT_THAT(array, HasSubstr("#SBATCH --partition=short\n"));
  EXPECT_THAT(array, HasSubstr("#SBATCH --time=1:00:00\n"));
  EXPECT_THAT(array, HasSubstr("'/opt/tandem/bin/tandem' bench '/home/a/env1.toml' --out "
                               "'/scratch/a/env1' '--seeds' '5' --shard "
                               "\"$SLURM_ARRAY_TASK_ID/8\""));
  const std::string merge = merge_script(sweep, 2);
  EXPECT_THAT(merge, HasSubstr("--merge --slurm --tasks 8 --cpus-per-task 2 --retries 2 "
                               "--partition 'short' --sbatch '--time=1:00:00'"));
  // Both are bash that parses.
  test::TempDir dir;
  for (const std::string* s : {&array, &merge}) {
    const auto file = dir.write("job.sbatch", *s);
    EXPECT_EQ(std::system(("bash -n " + file.string()).c_str()), 0) << *s;
  }
}

}  // namespace
}  // namespace tandem

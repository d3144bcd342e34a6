// The runner: it runs every configuration and seed, checks the solutions, resumes where it stopped.

#include "tandem/experiments/bench_runner.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <set>

#include "support/runs.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/experiments/report.hpp"
#include "tandem/experiments/runs_folder.hpp"

namespace tandem {
namespace {

using Fixture = test::ExperimentFixture;
using ::testing::HasSubstr;

TEST(BenchRunner, RunsEverythingChecksTheSolutionsAndResumesWhereItStopped) {
  Fixture f;
  test::TempDir dir;
  BenchOptions options;
  options.out_dir = dir.path() / "out";
  options.jobs = 2;
  const BenchResult first = run_experiment(f.experiment, f.problem, options);
  ASSERT_EQ(first.records.size(), 6u);
  EXPECT_EQ(first.ran, 6u);
  std::set<std::string> keys;
  for (const RunRecord& r : first.records) {
    EXPECT_TRUE(r.solved) << r.key();
    EXPECT_TRUE(r.path_valid) << r.key();
    keys.insert(r.key());
  }
  EXPECT_EQ(keys.size(), 6u);
  EXPECT_EQ(first.records[0].config, "birrt");
  EXPECT_EQ(first.records[3].config, "interactive-contact");
  EXPECT_GT(first.records[3].nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)], 0u);

  // Nothing left to do.
  const BenchResult again = run_experiment(f.experiment, f.problem, options);
  EXPECT_EQ(again.ran, 0u);
  EXPECT_EQ(again.resumed, 6u);

  // A kill: two complete lines and half of the third remain. The missing runs run again and
  // give the same trees (same seed, same operator).
  const std::filesystem::path runs = options.out_dir / "runs.jsonl";
  std::vector<std::string> lines;
  {
    std::ifstream in(runs);
    for (std::string l; std::getline(in, l);)
      lines.push_back(l);
  }
  ASSERT_EQ(lines.size(), 6u);
  write_file_atomically(runs, lines[0] + "\n" + lines[1] + "\n" + lines[2].substr(0, 40));
  const BenchResult resumed = run_experiment(f.experiment, f.problem, options);
  EXPECT_EQ(resumed.resumed, 2u);
  EXPECT_EQ(resumed.ran, 4u);
  ASSERT_EQ(resumed.records.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(resumed.records[i].key(), first.records[i].key());
    EXPECT_EQ(resumed.records[i].tree_digest, first.records[i].tree_digest)
        << first.records[i].key();
    EXPECT_EQ(resumed.records[i].nodes, first.records[i].nodes);
  }
  EXPECT_EQ(load_runs_file(runs, f.problem, f.experiment, false, nullptr).size(), 6u);
}

TEST(BenchRunner, RefusesAFolderOfAnotherExperimentAndAnOperatorWithoutAGuide) {
  Fixture f;
  test::TempDir dir;
  BenchOptions options;
  options.out_dir = dir.path();
  options.seeds = 1;
  (void)run_experiment(f.experiment, f.problem, options);
  Experiment other = f.experiment;
  other.time_limit = 5;
  EXPECT_THAT(
      test::error_message<InputError>([&] { return run_experiment(other, f.problem, options); }),
      HasSubstr(
          "runs.jsonl: holds runs of problem 'wall-with-gap' with a time limit of 30 "
          "s in virtual time; this experiment runs 'wall-with-gap' with 5 s in virtual time"));
  // Nor runs of the same experiment in human time.
  Experiment human = f.experiment;
  human.clock = "wall";
  EXPECT_THAT(
      test::error_message<InputError>([&] { return run_experiment(human, f.problem, options); }),
      HasSubstr("in virtual time; this experiment runs 'wall-with-gap' with 30 s in wall time"));

  Problem no_guide = f.problem;
  no_guide.guide.clear();
  test::TempDir dir2;
  options.out_dir = dir2.path();
  try {
    (void)run_experiment(f.experiment, no_guide, options);
    ADD_FAILURE() << "an interactive configuration without a guide ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no [guide]"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir2.path() / "runs.jsonl"));
}

TEST(BenchRunner, AStopFlagInterruptsWithoutRecordingTheInterruptedRuns) {
  Fixture f;
  test::TempDir dir;
  std::atomic<bool> stop{true};
  BenchOptions options;
  options.out_dir = dir.path();
  options.stop = &stop;
  const BenchResult r = run_experiment(f.experiment, f.problem, options);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(r.ran, 0u);
  EXPECT_TRUE(
      load_runs_file(dir.path() / "runs.jsonl", f.problem, f.experiment, false, nullptr).empty());
}

TEST(BenchRunner, InHumanTimeRunsOneAtATimeWithAPersonOnItsOwnThreadAndTwoCoresForAPlannerAlone) {
  Fixture f;
  f.experiment.clock = "wall";
  test::TempDir dir;
  BenchOptions options;
  options.out_dir = dir.path();
  options.seeds = 1;
  const BenchResult result = run_experiment(f.experiment, f.problem, options);
  ASSERT_EQ(result.records.size(), 2u);
  const RunRecord& alone = result.records[0];
  const RunRecord& together = result.records[1];
  EXPECT_EQ(alone.clock, "wall");
  EXPECT_EQ(together.clock, "wall");
  EXPECT_EQ(alone.threads, 2u);
  EXPECT_TRUE(together.solved);
  EXPECT_TRUE(together.path_valid);
  EXPECT_LE(together.time_s, 30.0);
  // The person's states reached the planner: it grew nodes toward them.
  EXPECT_GT(together.operator_iterations, 0u);
  EXPECT_GT(together.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)], 0u);
  const std::string report = format_report(f.experiment, f.problem, result.records, "cmd", {});
  EXPECT_THAT(report, HasSubstr("In human time"));
  EXPECT_THAT(report, HasSubstr("person waited s"));
}

}  // namespace
}  // namespace tandem

// Experiment files, the runner (resume, determinism, checked solutions), the statistics, OMPL's
// benchmark log and the report.

#include "tandem/experiments/experiment.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/experiments/bench_runner.hpp"
#include "tandem/experiments/ompl_log.hpp"
#include "tandem/experiments/report.hpp"
#include "tandem/experiments/statistics.hpp"

namespace tandem {
namespace {

Experiment parse(const std::string& text) {
  return parse_experiment(text, "x.toml", ".");
}

std::string error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ExperimentFile, SweepsAreProductsOnTopOfTheBaseAndTheirUnion) {
  const Experiment x = parse(R"(
name = "t"
problem = "cluttered-1"
seeds = 4
seed_start = 7
time_limit = 12.5
[base]
operator = "inexperienced"
[[sweep]]
mode = "interactive-contact"
alpha = [0.8, 0.2]
contact_samples = [1, 5, 10]
[[sweep]]
mode = "birrt"
[[sweep]]
mode = ["birrt"]  # the same configuration again: kept once
[report]
rows = "contact_samples"
columns = ["alpha"]
)");
  EXPECT_EQ(x.seeds, 4u);
  EXPECT_EQ(x.seed_start, 7u);
  EXPECT_DOUBLE_EQ(x.time_limit, 12.5);
  ASSERT_EQ(x.configs.size(), 7u);
  EXPECT_EQ(x.configs[0].label(),
            "interactive-contact alpha=0.8 contact_samples=1 operator=inexperienced");
  EXPECT_EQ(x.configs[6].label(), "birrt operator=inexperienced");
  const RunSpec s = x.configs[5].spec(3, 12.5);
  EXPECT_EQ(s.mode, "interactive-contact");
  EXPECT_TRUE(s.settings.interaction.contact);
  EXPECT_DOUBLE_EQ(s.settings.interaction.alpha, 0.2);
  EXPECT_EQ(s.settings.interaction.contact_samples, 10);
  EXPECT_EQ(s.operator_name, "inexperienced");
  EXPECT_EQ(s.settings.seed, 3u);
  EXPECT_EQ(x.report.title, "t");
}

TEST(ExperimentFile, TheProblemsHintsFillWhatAConfigurationLeavesOut) {
  const Experiment x =
      parse("name = \"t\"\nproblem = \"p\"\n[[sweep]]\nmode = [\"birrt\", \"rrt\"]\n");
  ProblemPlannerHints hints;
  hints.extend = "last-valid";
  hints.range = {{"birrt", 0.7}, {"rrt", 0.3}};
  EXPECT_EQ(x.configs[0].spec(1, 1, hints).settings.extend, ExtendMode::last_valid);
  EXPECT_DOUBLE_EQ(x.configs[0].spec(1, 1, hints).settings.range, 0.7);
  EXPECT_DOUBLE_EQ(x.configs[1].spec(1, 1, hints).settings.range, 0.3);
  EXPECT_EQ(x.configs[0].spec(1, 1).settings.extend, ExtendMode::classic);
}

TEST(ExperimentFile, FaultsNameTheFileAndLine) {
  const std::string head = "name = \"t\"\nproblem = \"p\"\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"problem = \"p\"\n", "x.toml:1: the experiment needs 'name'"},
      {head + "colour = 3\n", "x.toml:3: unknown key 'colour'"},
      {head + "[base]\nalfa = 0.5\n", "x.toml:4: unknown parameter 'alfa' (known: range, "},
      {head + "[base]\nalpha = \"high\"\n",
       "x.toml:4: alpha must be a number in [0, 1], not 'high'"},
      {head + "[[sweep]]\nalpha = [0.5, 1.5]\n",
       "x.toml:4: alpha must be a number in [0, 1], not 1.5"},
      {head + "[[sweep]]\nalpha = []\n", "x.toml:4: alpha has no values"},
      {head + "[[sweep]]\nmode = \"fast\"\n", "x.toml:4: unknown mode 'fast' (known: birrt, "},
      {head + "[[sweep]]\ncontact_samples = -2\n",
       "x.toml:4: contact_samples must be a whole number in [1, 100000], not -2"},
      {head + "[[sweep]]\ncontact_samples = 2.5\n",
       "x.toml:4: contact_samples must be a whole number in [1, 100000], not 2.5"},
      {head + "seeds = 0\n", "x.toml:3: seeds must be a positive integer"},
      {head + "time_limit = -1\n", "x.toml:3: time_limit must be a positive number"},
      {"name = \"../evil\"\nproblem = \"p\"\n", "x.toml:1: name may hold"},
      {head + "[report]\nrows = \"colour\"\n", "report.rows must name a run parameter"},
      {head + "[report]\nsize = 3\n", "x.toml:4: unknown key 'size' in report"},
      {head + "[base\n", "x.toml:3: invalid TOML"},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(c.text);
    EXPECT_NE(e.find(c.expected), std::string::npos) << "for\n" << c.text << "\ngot: " << e;
  }
}

TEST(Statistics, MedianIntervalFromOrderStatistics) {
  std::vector<double> v;
  for (int i = 20; i >= 1; --i)
    v.push_back(i);
  const Interval m = median_interval(v);
  EXPECT_DOUBLE_EQ(m.value, 10.5);
  ASSERT_TRUE(m.has_interval);
  // n = 20: ranks floor(10 - 1.96 sqrt(20) / 2) = 5 and ceil(11 + 4.38) = 16.
  EXPECT_DOUBLE_EQ(m.low, 5.0);
  EXPECT_DOUBLE_EQ(m.high, 16.0);
  const Interval few = median_interval({3.0, 1.0, 2.0});
  EXPECT_DOUBLE_EQ(few.value, 2.0);
  EXPECT_FALSE(few.has_interval);
  EXPECT_FALSE(median_interval({}).has_interval);
}

TEST(Statistics, WilsonIntervalOfASuccessRate) {
  const Interval none = success_interval(0, 10);
  EXPECT_DOUBLE_EQ(none.value, 0.0);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 0.2775, 1e-3);
  const Interval all = success_interval(20, 20);
  EXPECT_NEAR(all.low, 0.8389, 1e-3);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
}

TEST(RunRecords, RoundTripThroughAJsonLineAndRejectATornOne) {
  RunRecord r;
  r.problem = "p";
  r.config = "interactive alpha=0.5";
  r.params = {{"mode", "interactive"}, {"alpha", "0.5"}};
  r.seed = 9;
  r.time_limit_s = 30;
  r.status = "solved";
  r.solved = r.path_valid = true;
  r.time_s = 1.25;
  r.nodes = 100;
  r.edges = 98;
  r.nodes_by_source = {2, 50, 48, 0};
  r.tree_digest = "00ff";
  const std::string line = format_record(r);
  const auto back = parse_record(line);
  ASSERT_TRUE(back);
  EXPECT_EQ(format_record(*back), line);
  EXPECT_EQ(back->key(), "interactive alpha=0.5 #9");
  EXPECT_FALSE(parse_record(line.substr(0, line.size() / 2)));
  EXPECT_FALSE(parse_record("{}"));
}

/// The wall-with-gap problem with a guide through the gap, and an experiment of two
/// configurations x 3 seeds on it.
struct Fixture {
  Problem problem = test::wall_with_gap_problem();
  Experiment experiment;
  Fixture() {
    Config mid;
    mid.t = {0.0, 0.0, 0.0};
    problem.guide = {problem.start, mid, problem.goal};
    experiment = parse_experiment(R"(
name = "gap"
problem = "wall-with-gap"
seeds = 3
time_limit = 30
[[sweep]]
mode = ["birrt", "interactive-contact"]
[report]
rows = "mode"
)",
                                  "gap.toml", ".");
  }
};

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
  EXPECT_EQ(read_records(runs).size(), 6u);
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
  EXPECT_THROW((void)run_experiment(other, f.problem, options), InputError);

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
  EXPECT_TRUE(read_records(dir.path() / "runs.jsonl").empty());
}

TEST(OmplLog, OmplsOwnScriptReadsItIntoTheDatabasePlannerArenaUses) {
  const std::filesystem::path script = "/usr/bin/ompl_benchmark_statistics";
  if (!std::filesystem::exists(script))
    GTEST_SKIP() << script << " is absent (Debian package ompl-demos)";
  Fixture f;
  test::TempDir dir;
  BenchOptions options;
  options.out_dir = dir.path();
  options.seeds = 2;
  const BenchResult result = run_experiment(f.experiment, f.problem, options);
  OmplLogHeader header;
  header.version = "test";
  header.hostname = "host";
  header.date = "2026-01-01 00:00:00";
  const std::string log = format_ompl_log(f.experiment, f.problem, result.records, header);
  EXPECT_NE(log.find("2 planners\ntandem birrt\n"), std::string::npos);
  write_file_atomically(dir.path() / "ompl.log", log);
  const std::string db = (dir.path() / "r.db").string();
  const std::string cmd = script.string() + " " + (dir.path() / "ompl.log").string() + " -d " + db +
                          " > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  // Read the database back with Python's sqlite3 (what Planner Arena's loader uses).
  const std::string query =
      "python3 -c \"import sqlite3; c = sqlite3.connect('" + db +
      "'); print(c.execute('select count(*), sum(solved), sum(correct_solution), "
      "min(status) from runs').fetchone()); print(c.execute('select count(*) "
      "from plannerConfigs').fetchone()[0])\" > " +
      (dir.path() / "q.txt").string();
  ASSERT_EQ(std::system(query.c_str()), 0);
  EXPECT_EQ(read_text_file(dir.path() / "q.txt"), "(4, 4, 4, 6)\n2\n");
}

TEST(Report, TablesHaveARowPerConfigurationAndMarkCensoredMedians) {
  Fixture f;
  std::vector<RunRecord> records;
  for (int i = 0; i < 3; ++i) {
    RunRecord r;
    r.config = "birrt";
    r.params = {{"mode", "birrt"}};
    r.seed = static_cast<std::uint64_t>(i + 1);
    r.time_limit_s = 30;
    r.status = "timeout";
    r.time_s = 30.001;
    r.nodes = 1000;
    records.push_back(r);
    r.config = "interactive-contact";
    r.params = {{"mode", "interactive-contact"}};
    r.status = "solved";
    r.solved = r.path_valid = true;
    r.time_s = 0.5 * (i + 1);
    r.nodes = 10;
    records.push_back(r);
  }
  f.experiment.report.paper = {{"birrt", "2h45m"}};
  const std::string md =
      format_report(f.experiment, f.problem, records, "tandem bench gap.toml", {"a.svg", "b.svg"});
  EXPECT_NE(md.find("| birrt | 0/3 (0–56%) | > 30 | 1000 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| interactive-contact | 3/3 (44–100%) | 1 | 10 |"), std::string::npos) << md;
  EXPECT_NE(md.find("2h45m"), std::string::npos);
  EXPECT_NE(md.find("3 of 3 valid"), std::string::npos);
  EXPECT_NE(md.find("![time](a.svg)"), std::string::npos);

  const std::string svg = svg_plot("a <b> & c", "x", "y", {"1", "2"},
                                   {PlotSeries{"s", {Interval{1, 0.5, 2, true}, Interval{}}}});
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; c"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_EQ(svg.rfind("</svg>"), svg.size() - 7);
}

}  // namespace
}  // namespace tandem

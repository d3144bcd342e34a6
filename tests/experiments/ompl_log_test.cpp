// OMPL's benchmark log, read by OMPL's own script into the database Planner Arena uses.

#include "tandem/experiments/ompl_log.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "support/runs.hpp"
#include "tandem/core/text.hpp"
#include "tandem/experiments/bench_runner.hpp"

namespace tandem {
namespace {

using Fixture = test::ExperimentFixture;

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

}  // namespace
}  // namespace tandem

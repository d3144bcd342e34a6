// The tandem program as a user runs it: exit codes, messages, files.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/test_support.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/runs/portfolio.hpp"

namespace tandem {
namespace {

using test::run_tandem;
using test::TempDir;
using ::testing::HasSubstr;

const char* kWallScenario = R"(name = "wall"
[space]
min = [-3, -3, -1]
max = [3, 3, 1]
[object]
box = [1, 0.2, 0.2]
[[obstacle]]
name = "wall-south"
box = [0.1, 3.0, 2]
position = [0, -1.8, 0]
[[obstacle]]
name = "wall-north"
box = [0.1, 3.0, 2]
position = [0, 1.8, 0]
[start]
position = [-2, 0, 0]
[goal]
position = [2, 0, 0]
)";

/// An experiment on g.toml (the wall scenario with its guide): two seeds of BiRRT and of the
/// interactive planner.
constexpr const char* kWallExperiment = R"(name = "x"
problem = "g.toml"
seeds = 2
time_limit = 20
[[sweep]]
mode = ["birrt", "interactive"]
)";

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos)
    throw std::logic_error("fixture lacks '" + from + "'");
  return text.replace(at, from.size(), to);
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Bad input: exit code 2, nothing on stdout, exactly one line on stderr containing every
/// `expected`.
void expect_bad_input(const std::vector<std::string>& args,
                      const std::vector<std::string>& expected) {
  const test::RunResult r = run_tandem(args);
  std::string joined;
  for (const auto& a : args)
    joined += a + " ";
  EXPECT_EQ(r.exit_code, 2) << joined << "\n" << r.err;
  EXPECT_EQ(r.out, "") << joined;
  ASSERT_FALSE(r.err.empty()) << joined;
  EXPECT_EQ(r.err.back(), '\n') << joined;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << joined << "\n" << r.err;
  EXPECT_THAT(r.err, HasSubstr("tandem: error: ")) << joined;
  for (const auto& e : expected)
    EXPECT_THAT(r.err, HasSubstr(e)) << joined;
}

TEST(Cli, MissingProblemFile) {
  expect_bad_input({"plan", "/nonexistent/p.toml"}, {"/nonexistent/p.toml", "no such file"});
}

TEST(Cli, MalformedProblemFiles) {
  TempDir dir;
  expect_bad_input({"plan", dir.write("p.cfg", "[problem]\nrobot\n").string()},
                   {"p.cfg:2", "expected 'key = value'"});
  expect_bad_input({"plan", dir.write("p.toml", "[space\n").string()},
                   {"p.toml:1", "invalid TOML"});
  expect_bad_input({"plan", dir.write("p.txt", "hello").string()},
                   {"p.txt", "unknown problem format"});
  expect_bad_input({"plan", dir.path().string()}, {"is a folder"});
}

TEST(Cli, MalformedUrdfAndMeshes) {
  TempDir dir;
  dir.write("bad.urdf", "<robot name='x'><link name='a'>");
  dir.write("bad.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0\n");
  dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  dir.write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  const std::string box = "box = [0.1, 3.0, 2]\nposition = [0, -1.8, 0]";
  expect_bad_input(
      {"plan", dir.write("u.toml", with(kWallScenario, box, "urdf = \"bad.urdf\"")).string()},
      {"bad.urdf", "not a valid URDF"});
  expect_bad_input(
      {"plan", dir.write("m.toml", with(kWallScenario, box, "mesh = \"bad.stl\"")).string()},
      {"bad.stl", "cannot read mesh"});
  expect_bad_input(
      {"plan", dir.write("e.toml", with(kWallScenario, box, "mesh = \"points.obj\"")).string()},
      {"points.obj"});
  expect_bad_input(
      {"plan", dir.write("d.toml", with(kWallScenario, box, "mesh = \"line.obj\"")).string()},
      {"line.obj", "no triangles"});
}

TEST(Cli, ImpossibleProblems) {
  TempDir dir;
  expect_bad_input({"plan", dir.write("s.toml", with(kWallScenario, "position = [-2, 0, 0]",
                                                     "position = [0, 1, 0]"))
                                .string()},
                   {"s.toml", "the start is in collision with obstacle 'wall-north'"});
  expect_bad_input({"plan", dir.write("g.toml", with(kWallScenario, "position = [2, 0, 0]",
                                                     "position = [0, -1, 0]"))
                                .string()},
                   {"g.toml", "the goal is in collision with obstacle 'wall-south'"});
  expect_bad_input({"plan", dir.write("b.toml", with(kWallScenario, "position = [2, 0, 0]",
                                                     "position = [5, 0, 0]"))
                                .string()},
                   {"b.toml", "the goal", "outside the workspace bounds"});
}

TEST(Cli, UnwritableOutputsFailBeforePlanning) {
  TempDir dir;
  const auto problem = dir.write("w.toml", kWallScenario).string();
  expect_bad_input({"plan", problem, "--out", (dir.path() / "no" / "p.path").string()},
                   {"p.path", "cannot be written"});
  expect_bad_input({"plan", problem, "--svg", dir.path().string()}, {"is a folder"});
}

TEST(Cli, MalformedPathFile) {
  TempDir dir;
  const auto problem = dir.write("w.toml", kWallScenario);
  expect_bad_input({"check-path", problem.string(), dir.write("p.path", "1 2 3\n").string()},
                   {"p.path:1", "expected 7 numbers"});
  expect_bad_input({"check-path", problem.string(), (dir.path() / "none.path").string()},
                   {"none.path", "no such file"});
}

TEST(Cli, CheckPathValidationOptionsAreCheckedAsThePlannersAre) {
  const std::string path = (test::source_dir() / "scenes" / "cluttered-1.path").string();
  expect_bad_input({"check-path", "cluttered-1", path, "--validation", "bogus"},
                   {"--validation: must be one of exact, discrete, not 'bogus'"});
  expect_bad_input({"check-path", "cluttered-1", path, "--tolerance", "nan"},
                   {"--tolerance: must be a number at least 0, not nan"});
  expect_bad_input({"check-path", "cluttered-1", path, "--tolerance", "-1"},
                   {"--tolerance: must be a number at least 0, not -1"});
  EXPECT_EQ(run_tandem({"check-path", "cluttered-1", path, "--validation", "exact"}).exit_code, 0);
}

TEST(Cli, UnknownOptionsAndNonsensicalValues) {
  expect_bad_input({"plan", "cluttered-1", "--frobnicate"}, {"--frobnicate"});
  expect_bad_input({"plan", "cluttered-1", "--time-limit", "-1"}, {"--time-limit"});
  expect_bad_input({"plan", "cluttered-1", "--time-limit", "soon"}, {"--time-limit"});
  expect_bad_input({"plan", "cluttered-1", "--distance-grid", "maybe"},
                   {"--distance-grid: must be one of on, off, not 'maybe'"});
  expect_bad_input({"plan", "cluttered-1", "--threads", "-1"},
                   {"--threads: must be a whole number in [0, 256], not -1"});
  expect_bad_input({"plan", "cluttered-1", "--threads", "300"}, {"--threads"});
  expect_bad_input({"plan", "cluttered-1", "--threads", "two"}, {"--threads"});
  expect_bad_input({"plan", "cluttered-1", "--mode", "interactive", "--threads", "2"},
                   {"--threads: planner 'interactive' does not use threads"});
  expect_bad_input({"plan", "cluttered-1", "--range", "-1"}, {"--range"});
  expect_bad_input({"plan", "cluttered-1", "--seed", "-3"}, {"--seed"});
  expect_bad_input({"plan", "cluttered-1", "--planner", "prm"}, {"--planner"});
  expect_bad_input({"plan", "cluttered-1", "--goal-bias", "2"}, {"--goal-bias"});
  expect_bad_input({"plan"}, {"PROBLEM"});
  expect_bad_input({}, {"subcommand"});
  expect_bad_input({"fly"}, {"fly"});
}

TEST(Cli, PlansWritesJsonAndAPathThatChecks) {
  TempDir dir;
  const auto problem = dir.write("w.toml", kWallScenario).string();
  const auto out = (dir.path() / "w.path").string();
  const test::RunResult r = run_tandem({"plan", problem, "--seed", "3", "--json", "--out", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"solved", "time_s", "iterations", "nodes", "edges", "collision_checks",
                          "path_length", "seed"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(j["solved"].get<bool>());
  EXPECT_EQ(j["seed"].get<int>(), 3);
  // The default planner is the mixed portfolio: the winning member grew one tree (RRT) or two.
  EXPECT_EQ(j["mode"], std::string(kMixedPortfolio));
  const int trees = j["member_planner"] == "rrt" ? 1 : 2;
  EXPECT_EQ(j["edges"].get<int>(), j["nodes"].get<int>() - trees);
  EXPECT_GT(j["path_length"].get<double>(), 3.99);
  const test::RunResult check = run_tandem({"check-path", problem, out});
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_THAT(check.out, HasSubstr("valid"));
  EXPECT_THAT(check.out, HasSubstr("starts at the start, ends at the goal"));
}

TEST(Cli, SameSeedSamePath) {
  TempDir dir;
  const auto problem = dir.write("w.toml", kWallScenario).string();
  const auto a = (dir.path() / "a.path").string(), b = (dir.path() / "b.path").string();
  const auto c = (dir.path() / "c.path").string();
  // Unsimplified, the path shows the whole search (simplified, most runs give the same straight
  // line).
  ASSERT_EQ(run_tandem({"plan", problem, "--seed", "9", "--no-simplify", "--out", a}).exit_code, 0);
  ASSERT_EQ(run_tandem({"plan", problem, "--seed", "9", "--no-simplify", "--out", b}).exit_code, 0);
  ASSERT_EQ(run_tandem({"plan", problem, "--seed", "10", "--no-simplify", "--out", c}).exit_code,
            0);
  EXPECT_EQ(read(a), read(b));
  EXPECT_NE(read(a), read(c));
}

TEST(Cli, CheckPathReportsTheFirstInvalidIndex) {
  TempDir dir;
  const auto problem = dir.write("w.toml", kWallScenario).string();
  const auto path = dir.write("p.path", "-2 0 0 0 0 0 1\n-2 1 0 0 0 0 1\n2 1 0 0 0 0 1\n").string();
  const test::RunResult r = run_tandem({"check-path", problem, path});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.out, HasSubstr("invalid at index 2: the motion from state 1 to state 2 collides"));
}

TEST(Cli, ReportsNoSolutionWithExitCodeOne) {
  TempDir dir;
  const auto problem =
      dir.write("closed.toml", std::string(kWallScenario) +
                                   "[[obstacle]]\nname = \"plug\"\nbox = [0.1, 0.8, 2]\n");
  const test::RunResult r = run_tandem({"plan", problem.string(), "--time-limit", "0.3", "--json"});
  EXPECT_EQ(r.exit_code, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["solved"].get<bool>());
  EXPECT_EQ(j["status"], "timeout");
  EXPECT_TRUE(j["path_length"].is_null());
}

TEST(Cli, HelpDescribesEveryCommand) {
  const test::RunResult top = run_tandem({"--help"});
  EXPECT_EQ(top.exit_code, 0);
  for (const char* c : {"plan", "check-path", "scenes", "render", "bench"})
    EXPECT_THAT(top.out, HasSubstr(c));
  const test::RunResult plan = run_tandem({"plan", "--help"});
  EXPECT_EQ(plan.exit_code, 0);
  for (const char* o : {"--planner", "--seed", "--time-limit", "--range", "--out", "--json"}) {
    EXPECT_THAT(plan.out, HasSubstr(o));
  }
  for (const char* o : {"--mode", "--operator", "--alpha", "--contact-samples",
                        "--contact-distance", "--sampling", "--sigma", "--force-mix"}) {
    EXPECT_THAT(plan.out, HasSubstr(o));
  }
  EXPECT_EQ(run_tandem({"check-path", "--help"}).exit_code, 0);
  const test::RunResult bench = run_tandem({"bench", "--help"});
  EXPECT_EQ(bench.exit_code, 0);
  for (const char* o : {"EXPERIMENT", "--out", "--jobs", "--seeds", "--report-only"})
    EXPECT_THAT(bench.out, HasSubstr(o));
}

const char* kGuide = R"(
[guide]
keyframes = [{ position = [-2, 0, 0] }, { position = [0, 0.1, 0] }, { position = [2, 0, 0] }]
)";

TEST(Cli, HumanLoopOptionsRejectNonsense) {
  TempDir dir;
  const auto no_guide = dir.write("w.toml", kWallScenario).string();
  expect_bad_input({"plan", "cluttered-1", "--alpha", "0.3"},
                   {"--alpha", "planner 'birrt' does not use alpha"});
  expect_bad_input({"plan", "cluttered-1", "--operator", "inexperienced"},
                   {"--operator", "planner 'birrt' does not use operator"});
  for (const char* nonsense : {"nan", "inf", "-inf", "0.5x", ""}) {
    expect_bad_input({"plan", "cluttered-1", "--mode", "interactive", "--alpha", nonsense},
                     {"--alpha: must be a number in [0, 1], not"});
  }
  expect_bad_input(
      {"plan", "cluttered-1", "--mode", "interactive-contact", "--contact-samples", "2.5"},
      {"--contact-samples: must be a whole number in [1, 100000], not 2.5"});
  expect_bad_input({"plan", "cluttered-1", "--mode", "irrt", "--sampling", "wide"},
                   {"--sampling: must be one of mag, path, mag+cs, path+cs, not 'wide'"});
  expect_bad_input({"plan", "cluttered-1", "--mode", "interactive", "--alpha", "1.5"}, {"--alpha"});
  expect_bad_input({"plan", "cluttered-1", "--mode", "teleport"}, {"--mode"});
  expect_bad_input({"plan", "cluttered-1", "--mode", "interactive", "--operator", "clumsy"},
                   {"--operator", "clumsy"});
  expect_bad_input(
      {"plan", "cluttered-1", "--mode", "interactive", "--operator", "trace:/no/such.trace"},
      {"/no/such.trace"});
  expect_bad_input(
      {"plan", "cluttered-1", "--mode", "interactive-contact", "--contact-samples", "0"},
      {"--contact-samples"});
  expect_bad_input({"plan", "cluttered-1", "--mode", "irrt", "--sampling", "everywhere"},
                   {"--sampling"});
  expect_bad_input({"plan", no_guide, "--mode", "interactive"}, {"w.toml", "no [guide]"});
  // A guide of more than 12 keyframes is a path, not a gesture.
  std::string keys = "\n[guide]\nkeyframes = [";
  for (int i = 0; i < 13; ++i)
    keys += "{ position = [" + std::to_string(-2.0 + 0.3 * i) + ", 0, 0] },";
  keys += "]\n";
  const auto long_guide = dir.write("long.toml", std::string(kWallScenario) + keys).string();
  expect_bad_input({"plan", long_guide}, {"long.toml", "12"});
}

TEST(Cli, InteractivePlansCountNodesBySourceAndRepeatTheirTree) {
  TempDir dir;
  const auto problem = dir.write("g.toml", std::string(kWallScenario) + kGuide).string();
  std::vector<nlohmann::json> runs;
  for (const char* seed : {"4", "4", "5"}) {
    const test::RunResult r = run_tandem({"plan", problem, "--mode", "interactive-contact",
                                          "--alpha", "0.3", "--seed", seed, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    runs.push_back(nlohmann::json::parse(r.out));
  }
  const auto& j = runs[0];
  EXPECT_EQ(j["mode"], "interactive-contact");
  EXPECT_DOUBLE_EQ(j["alpha"].get<double>(), 0.3);
  int total = 0;
  for (const char* s : {"root", "random", "operator", "contact"})
    total += j["nodes_by_source"][s].get<int>();
  EXPECT_EQ(total, j["nodes"].get<int>());
  EXPECT_EQ(j["nodes_by_source"]["root"].get<int>(), 2);
  EXPECT_GT(j["nodes_by_source"]["operator"].get<int>(), 0);
  EXPECT_EQ(runs[0]["tree_digest"], runs[1]["tree_digest"]);
  EXPECT_NE(runs[0]["tree_digest"], runs[2]["tree_digest"]);
}

TEST(Cli, BenchRunsAnExperimentAndRejectsBadFiles) {
  TempDir dir;
  dir.write("g.toml", std::string(kWallScenario) + kGuide);
  const auto experiment = dir.write("x.toml", kWallExperiment);
  const auto out = (dir.path() / "out").string();
  const test::RunResult r = run_tandem({"bench", experiment.string(), "--out", out, "--jobs", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("4 runs recorded (4 now, 0 before), 4 solved, 4 solutions valid"));
  for (const char* f : {"runs.jsonl", "ompl.log", "report.md", "x-time.svg", "x-nodes.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / f)) << f;
  const test::RunResult again = run_tandem({"bench", experiment.string(), "--out", out});
  EXPECT_THAT(again.out, HasSubstr("(0 now, 4 before)"));
  EXPECT_EQ(run_tandem({"bench", experiment.string(), "--out", out, "--report-only"}).exit_code, 0);

  expect_bad_input({"bench", (dir.path() / "none.toml").string()}, {"none.toml"});
  const auto bad = dir.write("bad.toml", "name = \"b\"\nproblem = \"g.toml\"\n[base]\nalpha = 7\n");
  expect_bad_input({"bench", bad.string(), "--out", out},
                   {"bad.toml:4", "alpha must be a number in [0, 1], not 7"});
  expect_bad_input(
      {"bench", experiment.string(), "--out", (dir.path() / "fresh").string(), "--report-only"},
      {"runs.jsonl", "run the experiment first"});
  // A report of another experiment's runs (another time limit) is refused, not mixed.
  const auto other =
      dir.write("y.toml", with(kWallExperiment, "time_limit = 20", "time_limit = 30"));
  expect_bad_input({"bench", other.string(), "--out", out, "--report-only"},
                   {"runs.jsonl", "time limit of 20 s", "Use another --out folder"});
}

TEST(Cli, BenchShardsMergeIntoTheReportOfOneRun) {
  TempDir dir;
  dir.write("g.toml", std::string(kWallScenario) + kGuide);
  const auto experiment = dir.write("x.toml", kWallExperiment).string();
  const auto out = (dir.path() / "out").string();
  const test::RunResult one = run_tandem({"bench", experiment, "--out", out, "--shard", "1/2"});
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_THAT(one.out, HasSubstr("shard 1/2: 2 of 2 runs recorded (2 now, 0 before)"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "shards" / "shard-1-of-2.jsonl"));
  const test::RunResult partial =
      run_tandem({"bench", experiment, "--out", out, "--merge", "--tasks", "2"});
  EXPECT_EQ(partial.exit_code, 1);
  EXPECT_THAT(partial.out, HasSubstr("2 of 4 runs are missing"));
  EXPECT_THAT(partial.out, HasSubstr("shards with runs missing: 2 of 2"));
  ASSERT_EQ(run_tandem({"bench", experiment, "--out", out, "--shard", "2/2"}).exit_code, 0);
  const test::RunResult merged = run_tandem({"bench", experiment, "--out", out, "--merge"});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_THAT(merged.out, HasSubstr("4 runs recorded (from 2 shard files), 4 solved, 4 solutions "
                                    "valid"));
  for (const char* f : {"runs.jsonl", "ompl.log", "report.md"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / f)) << f;

  expect_bad_input({"bench", experiment, "--shard", "3/2"}, {"--shard", "K/N", "3/2"});
  expect_bad_input({"bench", experiment, "--shard", "1/2", "--merge"}, {"--shard", "--merge"});
  expect_bad_input({"bench", experiment, "--partition", "p"}, {"--partition", "--slurm"});
  for (const char* tasks : {"0", "1001", "nan", "-3"})
    expect_bad_input({"bench", experiment, "--merge", "--tasks", tasks}, {"--tasks", tasks});
  expect_bad_input({"bench", experiment, "--slurm", "--retries", "101"}, {"--retries", "101"});
  expect_bad_input({"bench", experiment, "--slurm", "--retries", "-1"}, {"--retries", "-1"});
  expect_bad_input({"bench", experiment, "--slurm", "--cpus-per-task", "0"},
                   {"--cpus-per-task", "0"});
  expect_bad_input({"bench", experiment, "--out", (dir.path() / "a b").string(), "--slurm"},
                   {"--out", "without blanks"});
  // No Slurm here, or one without this partition: refused before any run, naming --slurm.
  expect_bad_input({"bench", experiment, "--out", (dir.path() / "s").string(), "--slurm",
                    "--partition", "tandem-test-no-such-partition"},
                   {"--slurm", "sbatch"});
}

// The inputs the fuzzers found (fuzz/regression) are refused on the command line too: one line
// naming the file and the fault, exit code 2.
TEST(Cli, FuzzFoundInputsAreBadInput) {
  const auto regression = test::source_dir() / "fuzz" / "regression";
  const auto experiment = (regression / "experiment" / "seeds-float-out-of-range.toml").string();
  expect_bad_input({"bench", experiment}, {experiment, "seeds must be a positive integer"});
  const auto journal = (regression / "journal" / "float-where-a-whole-number-goes").string();
  expect_bad_input({"replay", journal}, {journal, "'seq' must be a whole number"});
  // The STEP target reads IGES when the input is not STEP; the command line goes by the name.
  TempDir dir;
  const auto iges = (dir.path() / "refused.igs").string();
  std::filesystem::copy_file(regression / "step" / "iges-refused-leak", iges);
  expect_bad_input({"parts", iges}, {iges, "not an IGES file in ASCII form"});
  // Binary bytes between a start and a terminate record crashed OCCT's IGES reader.
  const auto binary = (dir.path() / "binary.igs").string();
  std::filesystem::copy_file(regression / "step" / "iges-binary-records-crash-occt", binary);
  expect_bad_input({"parts", binary}, {binary, "not an IGES file in ASCII form"});
}

TEST(Cli, BuiltinScenesCanBeListedAndExported) {
  const test::RunResult list = run_tandem({"scenes"});
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_THAT(list.out, HasSubstr("cluttered-1"));
  const test::RunResult text = run_tandem({"scenes", "cluttered-1"});
  ASSERT_EQ(text.exit_code, 0);
  // The exported file is a scenario tandem reads back.
  TempDir dir;
  const auto file = dir.write("c1.toml", text.out);
  const auto path = (test::source_dir() / "scenes" / "cluttered-1.path").string();
  EXPECT_EQ(run_tandem({"check-path", file.string(), path}).exit_code, 0);
  expect_bad_input({"scenes", "nowhere"}, {"nowhere", "no built-in scene"});
}

TEST(Cli, RendersSvg) {
  TempDir dir;
  const auto svg = (dir.path() / "c1.svg").string();
  const auto path = (test::source_dir() / "scenes" / "cluttered-1.path").string();
  ASSERT_EQ(run_tandem({"render", "cluttered-1", path, "--out", svg}).exit_code, 0);
  const std::string text = read(svg);
  EXPECT_THAT(text, HasSubstr("<svg"));
  EXPECT_THAT(text, HasSubstr("<polyline"));
}

TEST(Cli, AnInteractiveSessionReplaysToTheIdenticalTree) {
  TempDir dir;
  const auto journal = dir.path() / "session.jsonl";
  const auto path = dir.path() / "live.path";
  const test::RunResult live = run_tandem({"interactive", "cluttered-1", "--headless", "--seed",
                                           "2", "--time-limit", "60", "--session", journal.string(),
                                           "--out", path.string(), "--digest-every", "0.002"});
  ASSERT_EQ(live.exit_code, 0) << live.out << live.err;
  EXPECT_THAT(live.out, HasSubstr("solved after"));
  EXPECT_THAT(live.out, HasSubstr("tandem replay " + journal.string()));
  const test::RunResult check = run_tandem({"check-path", "cluttered-1", path.string()});
  EXPECT_EQ(check.exit_code, 0) << check.out;

  const test::RunResult replay = run_tandem({"replay", journal.string()});
  EXPECT_EQ(replay.exit_code, 0) << replay.out << replay.err;
  EXPECT_THAT(replay.out, HasSubstr("identical to the session's tree"));

  // A journal cut short by a kill still replays, to its last recorded digest (a digest every 2 ms:
  // the session solves in a fraction of a second, and the cut needs one before the end).
  std::string text = read(journal);
  const auto end_record = text.rfind("\"end\":");
  ASSERT_NE(end_record, std::string::npos);
  const auto killed =
      dir.write("killed.jsonl", text.substr(0, text.rfind('\n', end_record) + 1 + 5));
  const test::RunResult partial = run_tandem({"replay", killed.string()});
  EXPECT_EQ(partial.exit_code, 0) << partial.out << partial.err;
  EXPECT_THAT(partial.out, HasSubstr("cut short"));
}

TEST(Cli, InteractiveAndReplayRejectBadInput) {
  TempDir dir;
  const std::string nowhere = (dir.path() / "nowhere").string();
  expect_bad_input({"interactive", "cluttered-1", "--web-root", nowhere},
                   {"nowhere", "front end is not built", "--headless"});
  expect_bad_input({"replay", "x.jsonl", "--serve", "--web-root", nowhere}, {"nowhere"});
  const std::string journal = (dir.path() / "s.jsonl").string();
  expect_bad_input(
      {"interactive", "cluttered-1", "--host", "nothost", "--port", "0", "--session", journal},
      {"--host", "not an IP address"});
  expect_bad_input({"interactive", "cluttered-1", "--port", "70000"}, {"--port"});
  expect_bad_input({"interactive", "cluttered-1", "--headless", "--mode", "birrt"},
                   {"--mode", "a live session needs a planner that takes an operator"});
  expect_bad_input({"replay", (dir.path() / "none.jsonl").string()}, {"none.jsonl"});
  const auto junk = dir.write("junk.jsonl", "{\"journal\":\"tandem session\",\"version\":9}\n");
  expect_bad_input({"replay", junk.string()}, {"junk.jsonl", "version 9"});
}

}  // namespace
}  // namespace tandem

// Experiment files: sweeps of configurations over a base, the problem's hints, faults by line.

#include "tandem/experiments/experiment.hpp"

#include <gtest/gtest.h>

#include "tandem/core/error.hpp"

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
  hints.values.push_back({"extend", std::string("last-valid"), "p.toml:9"});
  hints.range = {{"birrt", 0.7}, {"rrt", 0.3}};
  EXPECT_EQ(x.configs[0].spec(1, 1, hints).settings.extend, ExtendMode::last_valid);
  EXPECT_DOUBLE_EQ(x.configs[0].spec(1, 1, hints).settings.range, 0.7);
  EXPECT_DOUBLE_EQ(x.configs[1].spec(1, 1, hints).settings.range, 0.3);
  EXPECT_EQ(x.configs[0].spec(1, 1).settings.extend, ExtendMode::classic);
}

TEST(ExperimentFile, RunsInVirtualTimeUnlessItSaysWallClock) {
  const std::string head = "name = \"t\"\nproblem = \"cluttered-1\"\n";
  EXPECT_EQ(parse(head).clock, "virtual");
  EXPECT_EQ(parse(head + "clock = \"wall\"\n").clock, "wall");
  EXPECT_EQ(parse(head + "clock = \"virtual\"\n").clock, "virtual");
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
      {head + "[[sweep]]\nmode = \"fast\"\n",
       "x.toml:4: mode: unknown planner 'fast' (known: birrt, "},
      {head + "[[sweep]]\ncontact_samples = -2\n",
       "x.toml:4: contact_samples must be a whole number in [1, 100000], not -2"},
      {head + "[[sweep]]\ncontact_samples = 2.5\n",
       "x.toml:4: contact_samples must be a whole number in [1, 100000], not 2.5"},
      {head + "seeds = 0\n", "x.toml:3: seeds must be a positive integer"},
      // A float where an integer goes, out of an integer's range (a fuzz finding).
      {head + "seeds = 2e32\n", "x.toml:3: seeds must be a positive integer"},
      {head + "seeds = 4.0\n", "x.toml:3: seeds must be a positive integer"},
      {head + "time_limit = -1\n", "x.toml:3: time_limit must be a positive number"},
      {head + "clock = \"lunar\"\n",
       "x.toml:3: clock must be \"virtual\" (planner iterations) or \"wall\" (human time), not "
       "\"lunar\""},
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

}  // namespace
}  // namespace tandem

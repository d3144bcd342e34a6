// Behaviour kept across refactoring: for every built-in scene and every planner, fixed seeds and an
// iteration limit give the very trees recorded here (tree digest, node counts by source, collision
// checks), as `tandem plan` runs them (the scene's own settings, the modes' defaults, the experienced
// operator in virtual time). Also OMPL.app's Easy and cubicles with BiRRT (with ../shared).
//
// The values were first recorded before the parameter table, the target samplers and the planner
// registry replaced the earlier code, and recorded again when exact motion validation became the
// default; a change that is not meant to change behaviour must leave every row identical. When a
// change of behaviour is intended, the failure message prints the new row to paste here.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/test_support.hpp"
#include "tandem/runs/run.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

struct Golden {
  const char* problem;
  const char* mode;
  std::uint64_t seed;
  std::uint64_t max_iterations;
  // Expected:
  const char* status;
  std::uint64_t iterations;
  std::size_t nodes;
  std::size_t random, operator_, contact;
  std::uint64_t collision_checks;
  std::uint64_t digest;
};

std::string row(const Golden& g, const RunOutcome& o) {
  char buf[400];
  std::snprintf(
      buf, sizeof buf,
      "{\"%s\", \"%s\", %llu, %llu, \"%s\", %llu, %zu, %zu, %zu, %zu, %llu, 0x%016llxULL},",
      g.problem, g.mode, static_cast<unsigned long long>(g.seed),
      static_cast<unsigned long long>(g.max_iterations), std::string(to_string(o.status)).c_str(),
      static_cast<unsigned long long>(o.stats.iterations), o.stats.nodes,
      o.stats.nodes_by_source[1], o.stats.nodes_by_source[2], o.stats.nodes_by_source[3],
      static_cast<unsigned long long>(o.stats.collision_checks),
      static_cast<unsigned long long>(o.tree_digest));
  return buf;
}

RunOutcome run(const Golden& g, const Problem& problem) {
  // As `tandem plan PROBLEM --mode MODE --seed SEED --threads 1` makes it.
  RunSpec spec = default_spec(g.mode, problem.hints);
  spec.settings.seed = g.seed;
  spec.settings.threads = 1;
  spec.operator_seed = g.seed;
  spec.time_limit = 1e9;
  spec.max_iterations = g.max_iterations;
  return execute_run(problem, spec);
}

void expect_golden(const Golden& g, const Problem& problem) {
  const RunOutcome o = run(g, problem);
  SCOPED_TRACE("the row this run gives:\n" + row(g, o));
  EXPECT_EQ(to_string(o.status), g.status);
  EXPECT_EQ(o.stats.iterations, g.iterations);
  EXPECT_EQ(o.stats.nodes, g.nodes);
  EXPECT_EQ(o.stats.nodes_by_source[1], g.random);
  EXPECT_EQ(o.stats.nodes_by_source[2], g.operator_);
  EXPECT_EQ(o.stats.nodes_by_source[3], g.contact);
  EXPECT_EQ(o.stats.collision_checks, g.collision_checks);
  EXPECT_EQ(o.tree_digest, g.digest);
}

// clang-format off
const Golden kBuiltin[] = {
#include "golden_runs.inc"
};
const Golden kOmplApp[] = {
#include "golden_runs_omplapp.inc"
};
// clang-format on

class BuiltinGolden : public ::testing::TestWithParam<Golden> {};

TEST_P(BuiltinGolden, SameTreeAsRecorded) {
  const Golden& g = GetParam();
  expect_golden(g, load_problem(g.problem));
}

INSTANTIATE_TEST_SUITE_P(EveryScene, BuiltinGolden, ::testing::ValuesIn(kBuiltin),
                         [](const auto& p) {
                           std::string n = std::string(p.param.problem) + "_" + p.param.mode +
                                           "_seed" + std::to_string(p.param.seed);
                           for (char& c : n)
                             if (c == '-')
                               c = '_';
                           return n;
                         });

class OmplAppGolden : public ::testing::TestWithParam<Golden> {};

TEST_P(OmplAppGolden, SameTreeAsRecorded) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Golden& g = GetParam();
  const auto cfg = test::shared_dir() / "benchmarks" / "omplapp" / "3D" / g.problem;
  expect_golden(g, load_problem(cfg.string()));
}

INSTANTIATE_TEST_SUITE_P(EasyAndCubicles, OmplAppGolden, ::testing::ValuesIn(kOmplApp),
                         [](const auto& p) {
                           std::string n = std::string(p.param.problem) + "_seed" +
                                           std::to_string(p.param.seed);
                           for (char& c : n)
                             if (c == '-' || c == '.')
                               c = '_';
                           return n;
                         });

}  // namespace
}  // namespace tandem

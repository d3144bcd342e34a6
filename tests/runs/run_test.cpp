// execute_run (runs/run.hpp): a run is reproducible from its seed whatever its checker served
// before, as a bench worker's checker serves one run after another.

#include "tandem/runs/run.hpp"

#include <gtest/gtest.h>

#include "tandem/runs/run_spec.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

RunSpec birrt_spec(std::uint64_t seed) {
  RunSpec spec = default_spec("birrt", {});
  spec.mode = "birrt";
  spec.settings.seed = seed;
  spec.settings.threads = 1;
  spec.time_limit = 1e9;
  return spec;
}

TEST(Run, ACheckerThatServedEarlierRunsGivesTheSameTreeAsAFreshOne) {
  // The maze: the computer alone turns to its passage islands for a share of its queries, which
  // must be this run's queries, not the checker's since it was made.
  const Problem problem = load_problem("maze");
  ASSERT_GT(birrt_spec(2).settings.passages, 0.0);
  const RunOutcome fresh = execute_run(problem, birrt_spec(2));
  ASSERT_EQ(fresh.status, PlannerStatus::solved);

  CollisionChecker checker(problem.scene);
  ASSERT_EQ(execute_run(problem, birrt_spec(1), checker).status, PlannerStatus::solved);
  const RunOutcome again = execute_run(problem, birrt_spec(2), checker);
  EXPECT_EQ(again.tree_digest, fresh.tree_digest);
  EXPECT_EQ(again.stats.collision_checks, fresh.stats.collision_checks);
}

}  // namespace
}  // namespace tandem

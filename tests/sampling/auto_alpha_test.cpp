// Automatic authority sharing: the work follows each side's share of the progress per query.

#include "tandem/sampling/auto_alpha.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/problems.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/planning/rrt_connect.hpp"

namespace tandem {
namespace {

TEST(AutoAlpha, StartsEvenFollowsTheSideThatMakesProgressAndKeepsAFloor) {
  AutoAlpha a(1e-6);
  EXPECT_EQ(a.alpha(), 0.5);
  // The computer's iterations carry the trees on, the operator's do not.
  for (int k = 0; k < 5000; ++k) {
    a.record(true, 0.01, 1);
    a.record(false, 0.0, 1);
  }
  EXPECT_NEAR(a.alpha(), 1.0 - AutoAlpha::kFloor, 1e-12);
  EXPECT_NEAR(a.computer_rate(), 0.01, 1e-12);
  // Then the random trees stall before a passage and the operator's way goes on: within a few
  // memories, alpha turns to the operator.
  for (int k = 0; k < 5000; ++k) {
    a.record(true, 0.0, 1);
    a.record(false, 0.002, 1);
  }
  EXPECT_NEAR(a.alpha(), AutoAlpha::kFloor, 1e-12);
  // Both making progress: the queries shared in proportion to the progress per query. An
  // operator's iteration in contact mode costs ten of the computer's: the computer's 3/4 of the
  // queries are 7.5 of its iterations for every 0.25 of the operator's.
  for (int k = 0; k < 20000; ++k) {
    a.record(true, 0.003, 1);
    a.record(false, 0.01, 10);
  }
  EXPECT_NEAR(a.work_share(), 0.75, 0.01);
  EXPECT_NEAR(a.alpha(), 7.5 / 7.75, 0.005);
}

TEST(AutoAlpha, TheFloorIsAShareOfTheQueriesNotOfTheIterations) {
  AutoAlpha a(1e-6);
  // The operator's costly iterations make no progress: the computer gets 1 - kFloor of the
  // queries, so the operator's iterations, ten times dearer, are about 1% of them.
  for (int k = 0; k < 5000; ++k) {
    a.record(true, 0.01, 2);
    a.record(false, 0.0, 20);
  }
  EXPECT_EQ(a.work_share(), 1.0 - AutoAlpha::kFloor);
  EXPECT_NEAR(a.alpha(), 0.9 * 20 / (0.9 * 20 + 0.1 * 2), 1e-3);
  // And the other way: the computer keeps a tenth of the queries, half of the iterations.
  for (int k = 0; k < 20000; ++k) {
    a.record(true, 0.0, 2);
    a.record(false, 0.01, 20);
  }
  EXPECT_EQ(a.work_share(), AutoAlpha::kFloor);
  EXPECT_NEAR(a.alpha(), 0.1 * 20 / (0.1 * 20 + 0.9 * 2), 1e-3);
}

TEST(AutoAlpha, WithoutProgressOnEitherSideDriftsBackToEvenShares) {
  AutoAlpha a(1e-6);
  for (int k = 0; k < 2000; ++k)
    a.record(true, 0.01, 1);
  ASSERT_GT(a.alpha(), 0.8);
  for (int k = 0; k < 30000; ++k) {
    a.record(true, 0.0, 1);
    a.record(false, 0.0, 1);
  }
  EXPECT_NEAR(a.alpha(), 0.5, 0.05);
}

/// Uniform targets, and a record of what the planner credits them with.
class RecordingSampler final : public TargetSampler {
 public:
  explicit RecordingSampler(const SE3Space& space) : uniform_(space) {}
  void sample(const SampleRequest& request, std::vector<Target>& out) override {
    uniform_.sample(request, out);
  }
  bool wants_credit() const override { return true; }
  void credit(NodeSource source, double progress, std::uint64_t cost) override {
    EXPECT_EQ(source, NodeSource::random);
    EXPECT_GE(progress, 0.0);
    grown += progress;
    queries += cost;
    ++credits;
  }
  double grown = 0.0;
  std::uint64_t queries = 0;
  std::uint64_t credits = 0;

 private:
  UniformSampler uniform_;
};

/// What the planner credits adds up: the length of every motion the trees grew, and the queries.
TEST(AutoAlpha, ThePlannerCreditsTheLengthTheTreesGrewAndTheQueriesItCost) {
  test::ProblemFixture f(test::closed_problem());  // unsolvable: the trees only grow
  PlannerSettings settings;
  settings.seed = 3;
  auto owned = std::make_unique<RecordingSampler>(f.problem.space);
  RecordingSampler& sampler = *owned;
  RRTConnect planner(f.validator, f.problem.start, f.problem.goal, settings, std::move(owned));
  (void)planner.step();
  const CollisionCounters& c = f.checker.counters();
  const std::uint64_t before = c.state_checks + c.clearance_queries + c.distance_queries;
  const std::uint64_t credited_before = sampler.queries;
  for (int k = 0; k < 500; ++k)
    ASSERT_EQ(planner.step(), PlannerStatus::running);
  EXPECT_EQ(sampler.credits, 501u);  // one per target: its extension and the connection
  double edges = 0.0;
  for (const Tree* tree : planner.trees()) {
    for (NodeId n = 1; n < tree->size(); ++n)
      edges += f.problem.space.distance(tree->nodes[tree->parent[n]], tree->nodes[n]);
  }
  ASSERT_GT(edges, 0.0);
  EXPECT_NEAR(sampler.grown, edges, 1e-9 * edges);
  const std::uint64_t after = c.state_checks + c.clearance_queries + c.distance_queries;
  EXPECT_EQ(sampler.queries - credited_before, after - before);
}

/// The interactive planner with automatic alpha on the wall-with-gap problem: its alpha moves
/// away from even shares, stays a probability, and is reported; pinned, it is the setting.
TEST(AutoAlpha, ThePlannerCreditsProgressAndReportsTheAlphaInForce) {
  test::OperatorFixture f;
  PlannerSettings settings;
  settings.seed = 5;
  settings.interaction.auto_alpha = true;
  settings.interaction.alpha = 0.5;
  VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
  const Interaction interaction{&feed};
  auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                              &interaction);
  bool moved = false;
  for (int k = 0; k < 400 && planner->step() == PlannerStatus::running; ++k) {
    const double alpha = planner->stats().alpha;
    ASSERT_GT(alpha, 0.0);
    ASSERT_LT(alpha, 1.0);
    moved = moved || alpha != 0.5;
  }
  EXPECT_TRUE(moved);

  settings.interaction.auto_alpha = false;
  settings.interaction.alpha = 0.3;
  auto pinned = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                             &interaction);
  (void)pinned->step();
  (void)pinned->step();
  EXPECT_EQ(pinned->stats().alpha, 0.3);
  auto alone = make_planner("birrt", f.validator, f.problem.start, f.problem.goal, settings);
  (void)alone->step();
  EXPECT_TRUE(std::isnan(alone->stats().alpha));
}

}  // namespace
}  // namespace tandem

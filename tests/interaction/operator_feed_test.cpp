// The operator feeds: virtual time (periodic updates, an operator that watches the roadmap), and a
// live feed whose record replays the run exactly.

#include "tandem/interaction/operator_feed.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "support/problems.hpp"
#include "tandem/interaction/operator_thread.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using Fixture = test::OperatorFixture;
using test::all_nodes;

TEST(VirtualTimeFeed, UpdatesEveryPeriodAndCountsItsTime) {
  Fixture f;
  VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()), 10);
  const OperatorState* a = feed.at(0);
  const auto sequence = a->sequence;
  EXPECT_EQ(feed.at(9)->sequence, sequence);
  EXPECT_EQ(feed.at(10)->sequence, sequence + 1);
  EXPECT_EQ(feed.at(10)->time, 10.0);
  EXPECT_GT(feed.operator_seconds(), 0.0);
  EXPECT_FALSE(feed.at(10)->nearest.in_collision);
}

/// A roadmap at a fixed distance from everything.
struct FixedRoadmap final : RoadmapView {
  double d = 0.0;
  double distance_to_roadmap(const Config&) const override { return d; }
};

TEST(VirtualTimeFeed, AWatchingOperatorWaitsForTheRoadmap) {
  Fixture f;
  const auto source = f.operator_source();
  ASSERT_TRUE(std::isfinite(source->lead()));
  FixedRoadmap roadmap;
  VirtualTimeFeed near(OperatorModel(f.checker, source), 10);
  VirtualTimeFeed far(OperatorModel(f.checker, source), 10);
  for (std::uint64_t i = 0; i <= 1000; i += 10) {
    roadmap.d = 0.0;
    near.at(i, &roadmap);
    roadmap.d = 10.0 * source->lead();
    far.at(i, &roadmap);
  }
  // Near the roadmap the operator keeps its schedule; far from it, it never left the start.
  EXPECT_EQ(near.at(1000)->pace, 1000.0);
  EXPECT_TRUE(near.at(1000)->device.q_device == source->read(1000.0).q_device);
  EXPECT_EQ(far.at(1000)->pace, 0.0);
  EXPECT_EQ(far.operator_waits(), 100u);
  const auto* guide = dynamic_cast<const GuideFollower*>(source.get());
  ASSERT_NE(guide, nullptr);
  EXPECT_LT((far.at(1000)->device.q_device.t - guide->guide_pose(0.0).t).norm(),
            (near.at(1000)->device.q_device.t - guide->guide_pose(0.0).t).norm());
}

TEST(InteractiveBiRRT, ALiveSessionReplaysToTheSameTree) {
  // An operator thread publishes on the wall clock while the planner runs; the feed's record of
  // what the planner saw replays the run exactly.
  Fixture f;
  PlannerSettings settings;
  settings.seed = 9;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.alpha = 0.3;
  settings.interaction.contact = true;
  std::vector<Config> keys = {f.problem.start, f.problem.goal};
  const auto source = std::make_shared<GuideFollower>(
      f.problem.space, keys,
      operator_profile("experienced", f.problem.space, OperatorClock::seconds), 1);
  LatestValue<OperatorState> channel;
  std::vector<FeedRecord> record;
  std::vector<Config> live_nodes;
  {
    OperatorThread thread(OperatorModel(f.checker, source), channel, 2000.0);
    while (thread.published() < 5)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    LiveFeed feed(channel);
    const Interaction interaction{&feed};
    auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal,
                                settings, &interaction);
    Termination t;
    t.max_iterations = 4000;
    planner->solve(t);
    live_nodes = all_nodes(*planner);
    record = feed.record();
    thread.stop();
    EXPECT_GT(thread.achieved_rate(), 100.0);
  }
  ASSERT_FALSE(record.empty());
  ReplayFeed replay(record);
  const Interaction interaction{&replay};
  auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                              &interaction);
  Termination t;
  t.max_iterations = 4000;
  planner->solve(t);
  EXPECT_EQ(all_nodes(*planner), live_nodes);
}

TEST(LiveFeed, RecordsTheStateItHandsOutOnceAndAgainAfterARestart) {
  LatestValue<OperatorState> channel;
  LiveFeed feed(channel);
  EXPECT_EQ(feed.at(0), nullptr);
  OperatorState s;
  s.sequence = 1;
  channel.publish(s);
  ASSERT_NE(feed.at(3), nullptr);
  ASSERT_NE(feed.at(4), nullptr);
  ASSERT_EQ(feed.record().size(), 1u) << "the same state recorded twice";
  EXPECT_EQ(feed.record()[0].iteration, 3u);
  feed.take_record();
  feed.restart();  // a new planner, and no new state since
  ASSERT_NE(feed.at(0), nullptr);
  ASSERT_EQ(feed.record().size(), 1u) << "the new planner's first state is not in its record";
  EXPECT_EQ(feed.record()[0].iteration, 0u);
  EXPECT_EQ(feed.record()[0].state.sequence, 1u);
}

}  // namespace
}  // namespace tandem

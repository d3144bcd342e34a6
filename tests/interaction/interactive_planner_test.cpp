// The interactive BiRRT (Blin et al. 2016, Algorithms 1-3) driven by simulated operators.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "support/test_support.hpp"
#include "tandem/interaction/operator_thread.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

/// The wall with a gap, start and goal far from the gap (the straight line between them is
/// blocked), and a guide through the gap.
Problem detour_problem() {
  Problem p = test::wall_with_gap_problem();
  p.start.t = {-2, 2, 0};
  p.goal.t = {2, 2, 0};
  return p;
}

struct Fixture {
  Problem problem = detour_problem();
  CollisionChecker checker{problem.scene};
  MotionValidator validator{problem.space, checker};

  std::shared_ptr<const OperatorSource> operator_source(const std::string& profile = "experienced",
                                                        std::uint64_t seed = 1) const {
    std::vector<Config> keys(4);
    keys[0] = problem.start;
    keys[1].t = {-0.8, 0.0, 0.0};
    keys[2].t = {0.8, 0.0, 0.0};
    keys[3] = problem.goal;
    return std::make_shared<GuideFollower>(
        problem.space, keys, operator_profile(profile, problem.space, OperatorClock::ticks), seed);
  }
};

/// All nodes of all trees, in order.
std::vector<Config> all_nodes(const Planner& p) {
  std::vector<Config> out;
  for (const Tree* t : p.trees())
    out.insert(out.end(), t->nodes.begin(), t->nodes.end());
  return out;
}

TEST(InteractiveBiRRT, AtAlphaOneIsExactlyBiRRT) {
  Fixture f;
  PlannerSettings settings;
  settings.seed = 11;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.alpha = 1.0;
  settings.interaction.contact = true;
  auto plain = make_planner("birrt", f.validator, f.problem.start, f.problem.goal, settings);
  ASSERT_EQ(plain->solve(Termination{}), PlannerStatus::solved);

  VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
  const Interaction interaction{&feed};
  auto interactive = make_planner("interactive", f.validator, f.problem.start, f.problem.goal,
                                  settings, &interaction);
  ASSERT_EQ(interactive->solve(Termination{}), PlannerStatus::solved);
  EXPECT_EQ(all_nodes(*plain), all_nodes(*interactive));
  EXPECT_EQ(plain->solution(), interactive->solution());
  EXPECT_EQ(interactive->stats().operator_iterations, 0u);
}

TEST(InteractiveBiRRT, TheOperatorAloneGrowsTheTreeAlongTheGuide) {
  Fixture f;
  PlannerSettings settings;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.alpha = 0.0;
  const auto source = f.operator_source();
  VirtualTimeFeed feed(OperatorModel(f.checker, source));
  const Interaction interaction{&feed};
  auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                              &interaction);
  Termination t;
  t.max_iterations = 200000;
  ASSERT_EQ(planner->solve(t), PlannerStatus::solved);
  const PlannerStats& s = planner->stats();
  EXPECT_EQ(s.nodes_by_source[static_cast<std::size_t>(NodeSource::random)], 0u);
  EXPECT_GT(s.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)], 0u);
  EXPECT_EQ(s.operator_iterations, s.iterations);
  // The path passes the gap where the operator did.
  const PathCheck check = check_path(planner->solution(), f.validator);
  EXPECT_TRUE(check.valid) << check.describe();
  // The trees grew where the operator went: toward the gap and through it (once through, the trees
  // may meet before the operator reaches the goal).
  const auto* guide = dynamic_cast<const GuideFollower*>(source.get());
  for (double u : {0.25, 0.5}) {
    const Eigen::Vector3d p = guide->guide_pose(u * guide->guide_length()).t;
    double nearest = 1e9;
    for (const Tree* tree : planner->trees()) {
      for (const Config& q : tree->nodes)
        nearest = std::min(nearest, (q.t - p).norm());
    }
    EXPECT_LT(nearest, 0.2) << "at " << p.transpose();
  }
}

TEST(InteractiveBiRRT, SameSeedSameOperatorSameTree) {
  auto run = [](std::uint64_t seed) {
    Fixture f;
    PlannerSettings settings;
    settings.seed = seed;
    settings.extend = ExtendMode::last_valid;
    settings.interaction.alpha = 0.5;
    settings.interaction.contact = true;
    VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source("inexperienced", 3)));
    const Interaction interaction{&feed};
    auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal,
                                settings, &interaction);
    Termination t;
    t.max_iterations = 3000;
    planner->solve(t);
    return all_nodes(*planner);
  };
  EXPECT_EQ(run(4), run(4));
  EXPECT_NE(run(4), run(5));
}

/// The wall with a gap, where the guide runs along the wall's face: contact mode.
TEST(InteractiveBiRRT, ContactSamplingSlidesOnTheObstacle) {
  Fixture f;
  PlannerSettings settings;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.alpha = 0.0;
  settings.interaction.contact = true;
  settings.interaction.contact_distance = 0.2;
  std::vector<Config> keys(3);
  keys[0] = f.problem.start;
  keys[1].t = {-0.6, 2.0, 0.0};  // the bar's end 5 cm from the wall's face
  keys[2].t = {-0.6, 0.0, 0.0};
  const auto source = std::make_shared<GuideFollower>(
      f.problem.space, keys, operator_profile("experienced", f.problem.space, OperatorClock::ticks),
      2);
  VirtualTimeFeed feed(OperatorModel(f.checker, source));
  const Interaction interaction{&feed};
  auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                              &interaction);
  Termination t;
  t.max_iterations = 6000;
  planner->solve(t);
  const PlannerStats& s = planner->stats();
  EXPECT_GT(s.contact_entries, 0u);
  const auto contact_nodes = s.nodes_by_source[static_cast<std::size_t>(NodeSource::contact)];
  EXPECT_GT(contact_nodes, 0u);
  // Contact nodes end at the wall: within the contact distance of it.
  CollisionChecker checker = f.checker.clone();
  std::size_t near_wall = 0;
  for (const Tree* tree : planner->trees()) {
    for (std::size_t i = 0; i < tree->size(); ++i) {
      if (tree->source[i] != NodeSource::contact)
        continue;
      near_wall += checker.nearest_obstacle(tree->nodes[i]).distance <= 0.2;
    }
  }
  EXPECT_GT(static_cast<double>(near_wall), 0.9 * static_cast<double>(contact_nodes));
}

TEST(InteractiveBiRRT, ParametersChangeWhilePlanning) {
  Fixture f;
  PlannerSettings settings;
  settings.extend = ExtendMode::last_valid;
  InteractionSettings operator_only;
  operator_only.alpha = 0.0;
  InteractionParameters parameters(operator_only);
  VirtualTimeFeed feed(OperatorModel(f.checker, f.operator_source()));
  const Interaction interaction{&feed, &parameters};
  auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal, settings,
                              &interaction);
  Termination t;
  t.max_iterations = 300;
  planner->solve(t);
  const auto random_before =
      planner->stats().nodes_by_source[static_cast<std::size_t>(NodeSource::random)];
  const auto operator_before = planner->stats().operator_iterations;
  EXPECT_EQ(random_before, 0u);
  EXPECT_EQ(operator_before, 300u);
  InteractionSettings computer_only;
  computer_only.alpha = 1.0;
  parameters.set(computer_only);
  planner->solve(t);
  EXPECT_EQ(planner->stats().operator_iterations, operator_before);
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

TEST(Pacer, FollowsTimeNearTheRoadmapAndGoesBackAwayFromIt) {
  Pacer never(std::numeric_limits<double>::infinity());
  EXPECT_EQ(never.advance(50.0, 1e9), 50.0);  // it does not look

  Pacer p(1.0);
  EXPECT_EQ(p.advance(10.0, 0.5), 10.0);  // the roadmap is near: it moves on
  EXPECT_EQ(p.advance(30.0, 0.9), 30.0);
  EXPECT_EQ(p.advance(35.0, 1.5), 25.0);  // too far: it goes back for as long
  EXPECT_EQ(p.waits(), 1u);
  EXPECT_EQ(p.advance(35.0, 1.5), 25.0);  // no time passed
  EXPECT_EQ(p.advance(100.0, 2.0), 0.0);  // never before the start of its way
  EXPECT_EQ(p.advance(110.0, 0.0), 10.0);
}

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

TEST(InteractiveBiRRT, TheSimulatedOperatorWatchesTheRoadmap) {
  // The operator alone (alpha = 0): the tree follows it through the gap, slower than it moves. A
  // watching operator never gets much more than its lead ahead of the roadmap; one that does not
  // watch runs far ahead.
  Fixture f;
  const auto profile = operator_profile("experienced", f.problem.space, OperatorClock::ticks);
  auto farthest = [&](double lead) {
    OperatorProfile p = profile;
    p.lead = lead;
    std::vector<Config> keys = {f.problem.start, Config{}, f.problem.goal};
    keys[1].t = {0.0, 0.0, 0.0};
    VirtualTimeFeed feed(
        OperatorModel(f.checker, std::make_shared<GuideFollower>(f.problem.space, keys, p, 1)), 10);
    const Interaction interaction{&feed};
    PlannerSettings settings;
    settings.seed = 5;
    settings.extend = ExtendMode::last_valid;
    settings.interaction.alpha = 0.0;
    auto planner = make_planner("interactive", f.validator, f.problem.start, f.problem.goal,
                                settings, &interaction);
    double d = 0.0;
    while (planner->step() == PlannerStatus::running && planner->stats().iterations < 20000) {
      // What the planner will see next (the same roadmap, so the same state).
      const OperatorState* s = feed.at(planner->stats().iterations, planner.get());
      d = std::max(d, planner->distance_to_roadmap(s->device.q_device));
    }
    return d;
  };
  const double tremor = f.problem.space.distance(
      Config{}, Config{Eigen::Vector3d::Constant(profile.tremor_translation),
                       Eigen::Quaterniond(
                           Eigen::AngleAxisd(profile.tremor_rotation, Eigen::Vector3d::UnitZ()))});
  // Its lead, one update's motion, and its tremor then and now (fixed seeds: no flakiness).
  const double bound = profile.lead + 10.0 * profile.speed + 2.0 * tremor;
  EXPECT_LT(farthest(profile.lead), bound);
  EXPECT_GT(farthest(std::numeric_limits<double>::infinity()), bound);
}

}  // namespace
}  // namespace tandem

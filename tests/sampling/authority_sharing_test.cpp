// Authority sharing with contact sampling (Blin et al. 2016, Algorithms 1-3), through the
// "interactive" planner (RRT-Connect with an AuthoritySharing sampler) driven by simulated
// operators.

#include "tandem/sampling/authority_sharing.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/problems.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using Fixture = test::OperatorFixture;
using test::all_nodes;

TEST(InteractiveBiRRT, AtAlphaOneIsExactlyBiRRT) {
  Fixture f;
  PlannerSettings settings;
  settings.seed = 11;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.alpha = 1.0;
  settings.interaction.contact = true;
  settings.guide = 0.0;  // the computer alone's workspace guide is not the papers' BiRRT
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

// The I-RRT (Taix and Flavigne 2011) and its Gaussian shooting area.

#include "tandem/planning/irrt.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/operators/guide_follower.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"
#include "tandem/sampling/gaussian_shooter.hpp"

namespace tandem {
namespace {

TEST(GaussianShot, IsCentredAndStretchedAlongTheForce) {
  const SE3Space space(SpaceKind::se3, Bounds{{-100, -100, -100}, {100, 100, 100}});
  Config centre;
  centre.t = {1, 2, 3};
  const double sigma_t = 0.5, sigma_r = 0.1;
  Twist force = Twist::Zero();
  force.x() = 2 * sigma_t;  // strength 2 in units of sigma: stretched 3 times along x
  Rng rng(1);
  const int n = 40000;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), var = Eigen::Vector3d::Zero();
  double angle = 0.0;
  for (int i = 0; i < n; ++i) {
    const Config q = gaussian_shot(space, centre, force, sigma_t, sigma_r, rng);
    const Eigen::Vector3d d = q.t - centre.t;
    mean += d / n;
    var += d.cwiseProduct(d) / n;
    angle += SE3Space::rotation_angle(q.q, centre.q) / n;
  }
  EXPECT_LT(mean.norm(), 0.05);
  EXPECT_NEAR(std::sqrt(var.x()), 3 * sigma_t, 0.05);
  EXPECT_NEAR(std::sqrt(var.y()), sigma_t, 0.02);
  EXPECT_NEAR(std::sqrt(var.z()), sigma_t, 0.02);
  // Rotation: a 3-D normal rotation vector of deviation sigma_r has mean length sigma_r sqrt(8 /
  // pi).
  EXPECT_NEAR(angle, sigma_r * std::sqrt(8.0 / std::numbers::pi), 0.01);
}

TEST(GaussianShot, StaysInThePlaneAndInTheBounds) {
  const SE3Space plane(SpaceKind::planar, Bounds{{0, 0, 0}, {1, 1, 0}});
  Rng rng(2);
  for (int i = 0; i < 2000; ++i) {
    const Config q =
        gaussian_shot(plane, plane.planar_config(0.9, 0.5, 0.0), Twist::Ones(), 0.3, 0.5, rng);
    ASSERT_TRUE(plane.satisfies_bounds(q));
    ASSERT_NEAR((q.q * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  }
}

struct Fixture {
  Problem problem = [] {
    Problem p = test::wall_with_gap_problem();
    p.start.t = {-2, 2, 0};
    p.goal.t = {2, 2, 0};
    return p;
  }();
  CollisionChecker checker{problem.scene};
  MotionValidator validator{problem.space, checker};
  std::shared_ptr<const OperatorSource> source() const {
    std::vector<Config> keys(4);
    keys[0] = problem.start;
    keys[1].t = {-0.8, 0.0, 0.0};
    keys[2].t = {0.8, 0.0, 0.0};
    keys[3] = problem.goal;
    return std::make_shared<GuideFollower>(
        problem.space, keys, operator_profile("experienced", problem.space, OperatorClock::ticks),
        1);
  }
};

TEST(IRRT, NeedsAnOperator) {
  Fixture f;
  EXPECT_THROW(
      make_planner("irrt", f.validator, f.problem.start, f.problem.goal, PlannerSettings{}),
      std::invalid_argument);
}

class IrrtModes : public ::testing::TestWithParam<IrrtSampling> {};

TEST_P(IrrtModes, FollowTheUserToTheGoal) {
  Fixture f;
  PlannerSettings settings;
  settings.extend = ExtendMode::last_valid;
  settings.interaction.sampling = GetParam();
  VirtualTimeFeed feed(OperatorModel(f.checker, f.source()));
  LatestValue<Guidance> guidance;
  const Interaction interaction{&feed, nullptr, &guidance};
  auto planner =
      make_planner("irrt", f.validator, f.problem.start, f.problem.goal, settings, &interaction);
  Termination t;
  t.max_iterations = 400000;
  ASSERT_EQ(planner->solve(t), PlannerStatus::solved);
  EXPECT_TRUE(check_path(planner->solution(), f.validator).valid);
  const PlannerStats& s = planner->stats();
  EXPECT_GT(s.nodes_by_source[static_cast<std::size_t>(NodeSource::operator_)], s.nodes / 2);
  EXPECT_EQ(s.extensions_collision + s.extensions_reached + s.extensions_obstacle, s.iterations);
  ASSERT_NE(guidance.latest(), nullptr);
  EXPECT_GT(guidance.latest()->iteration, 0u);
}

INSTANTIATE_TEST_SUITE_P(AllModes, IrrtModes,
                         ::testing::Values(IrrtSampling::mag, IrrtSampling::path,
                                           IrrtSampling::mag_cs, IrrtSampling::path_cs),
                         [](const auto& test_info) {
                           std::string n(to_string(test_info.param));
                           for (char& c : n)
                             c = c == '+' ? '_' : c;
                           return n;
                         });

TEST(IRRT, UniformSamplesOnlyInCsModes) {
  for (IrrtSampling mode : {IrrtSampling::mag, IrrtSampling::mag_cs}) {
    Fixture f;
    PlannerSettings settings;
    settings.goal_bias = 0.0;
    settings.extend = ExtendMode::last_valid;
    settings.interaction.sampling = mode;
    VirtualTimeFeed feed(OperatorModel(f.checker, f.source()));
    const Interaction interaction{&feed};
    auto planner =
        make_planner("irrt", f.validator, f.problem.start, f.problem.goal, settings, &interaction);
    Termination t;
    t.max_iterations = 3000;
    planner->solve(t);
    const auto random =
        planner->stats().nodes_by_source[static_cast<std::size_t>(NodeSource::random)];
    if (mode == IrrtSampling::mag) {
      EXPECT_EQ(random, 0u);
    } else {
      EXPECT_GT(random, 0u);
    }
  }
}

TEST(IRRT, TheGuidanceForcePullsTheUserTowardTheTree) {
  // The user runs ahead of the tree (it cannot follow through the wall): F_a points back toward the
  // nodes, and nodes that keep failing carry a collision label.
  Fixture f;
  std::vector<Config> keys(2);
  keys[0] = f.problem.start;
  keys[1].t = {2, 2, 0};  // straight through the wall
  const auto source = std::make_shared<GuideFollower>(
      f.problem.space, keys, operator_profile("experienced", f.problem.space, OperatorClock::ticks),
      1);
  PlannerSettings settings;
  settings.goal_bias = 0.0;
  settings.extend = ExtendMode::last_valid;
  VirtualTimeFeed feed(OperatorModel(f.checker, source));
  LatestValue<Guidance> guidance;
  const Interaction interaction{&feed, nullptr, &guidance};
  IRRT planner(f.validator, f.problem.start, f.problem.goal, settings, interaction);
  Termination t;
  t.max_iterations = 20000;
  planner.solve(t);
  const Twist fa = guidance.latest()->force;
  EXPECT_LT(fa.x(), -0.5);  // the user is past the wall at x = 2, the tree stays at x < 0
  double worst = 0.0;
  for (const auto& l : planner.labels())
    worst = std::max(worst, l.collision_label);
  EXPECT_GT(worst, 0.1);
  for (std::size_t i = 0; i < planner.labels().size(); ++i) {
    ASSERT_DOUBLE_EQ(planner.labels()[i].distance_to_goal,
                     f.problem.space.distance(planner.trees()[0]->nodes[i], f.problem.goal));
  }
}

TEST(IRRT, IsDeterministicForASeedAndAnOperator) {
  auto run = [](std::uint64_t seed) {
    Fixture f;
    PlannerSettings settings;
    settings.seed = seed;
    settings.interaction.sampling = IrrtSampling::path_cs;
    VirtualTimeFeed feed(OperatorModel(f.checker, f.source()));
    const Interaction interaction{&feed};
    auto planner =
        make_planner("irrt", f.validator, f.problem.start, f.problem.goal, settings, &interaction);
    Termination t;
    t.max_iterations = 2000;
    planner->solve(t);
    return planner->trees()[0]->nodes;
  };
  EXPECT_EQ(run(3), run(3));
  EXPECT_NE(run(3), run(4));
}

}  // namespace
}  // namespace tandem

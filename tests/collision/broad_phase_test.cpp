// The broad phase (the tree of obstacle boxes) against the linear loop over the boxes: the same
// answers on uniform samples and on configurations a hair either side of contact, of every shipped
// problem and of generated many-part scenes.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/scene/box_field.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

struct Tally {
  int free = 0, colliding = 0, surfaces = 0;
};

void expect_same_surfaces(const std::vector<NearestObstacle>& a,
                          const std::vector<NearestObstacle>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].obstacle, b[i].obstacle);
    EXPECT_EQ(a[i].distance, b[i].distance);
    EXPECT_EQ(a[i].point_on_obstacle, b[i].point_on_obstacle);
  }
}

/// Every query of the linear checker and the tree's on the configurations.
Tally compare(const Problem& p, const std::vector<Config>& configs) {
  CollisionChecker linear(p.scene), tree(p.scene);
  linear.use_broad_phase(BroadPhase::linear);
  tree.use_broad_phase(BroadPhase::tree);
  EXPECT_FALSE(linear.uses_tree());
  EXPECT_TRUE(tree.uses_tree());
  const double within = 0.05 * p.space.bounds().extent().maxCoeff();
  const double cap = 0.2 * p.space.bounds().extent().maxCoeff();
  constexpr double kGrow = 1.0 + CollisionChecker::kClearanceRelativeError;
  Tally t;
  for (const Config& q : configs) {
    const bool free = linear.is_collision_free(q);
    EXPECT_EQ(tree.is_collision_free(q), free);
    const NearestObstacle a = linear.nearest_obstacle(q), b = tree.nearest_obstacle(q);
    EXPECT_EQ(a.in_collision, b.in_collision);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.obstacle, b.obstacle);  // ties and collisions: the first pair in the scene's order
    EXPECT_EQ(a.point_on_obstacle, b.point_on_obstacle);
    EXPECT_EQ(a.point_on_object, b.point_on_object);
    EXPECT_EQ(a.in_collision, !free);
    const auto surfaces = linear.nearest_surfaces(q, within);
    expect_same_surfaces(surfaces, tree.nearest_surfaces(q, within));
    // A clearance bound depends on the order FCL meets the parts in: the tree keeps the scene's.
    const double bound = linear.clearance_bound(q, cap);
    EXPECT_EQ(tree.clearance_bound(q, cap), bound);
    if (a.in_collision) {
      // (FCL's GJK leaves boxes that only just touch a rounding error apart.)
      EXPECT_LE(bound, 1e-12);
    } else {
      EXPECT_LE(bound, a.distance * (1.0 + 1e-9) + 1e-12);
      EXPECT_GE(bound, std::min(cap, a.distance) / kGrow - 1e-9);
    }
    (free ? t.free : t.colliding) += 1;
    t.surfaces += static_cast<int>(surfaces.size());
  }
  return t;
}

std::vector<Config> configs_of(const Problem& p, std::size_t near_pairs, int uniform) {
  std::vector<Config> configs = test::near_contact_configs(p, 23, near_pairs);
  Rng rng(29);
  for (int i = 0; i < uniform; ++i)
    configs.push_back(p.space.sample_uniform(rng));
  return configs;
}

TEST(BroadPhase, SameAnswersAsTheLinearLoopOnEveryShippedProblem) {
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    const Tally t = compare(p, configs_of(p, 20, 100));
    EXPECT_GT(t.free, 0);
    EXPECT_GT(t.colliding, 0);
  }
}

TEST(BroadPhase, SameAnswersAsTheLinearLoopOnManyPartScenes) {
  for (const std::size_t parts : {std::size_t{40}, std::size_t{400}, std::size_t{2000}}) {
    SCOPED_TRACE(parts);
    const Problem p = box_field_problem({.parts = parts, .seed = parts});
    const Tally t = compare(p, configs_of(p, 20, 150));
    EXPECT_GT(t.free, 0);
    EXPECT_GT(t.colliding, 0);
    EXPECT_GT(t.surfaces, 0);  // the bar near several boxes at once was tried
  }
}

TEST(BroadPhase, TiesGoToTheFirstPartInTheScenesOrder) {
  // Pairs of equal boxes in a row, the bar midway between the two of a pair: exactly as near to
  // both. Whichever the tree meets first, the answer is the linear loop's: the first in the
  // scene's order.
  Scene scene;
  scene.object.name = "bar";
  scene.object.parts.push_back(
      {Box{Eigen::Vector3d(0.6, 0.05, 0.05)}, Eigen::Isometry3d::Identity()});
  for (int i = 0; i < 40; ++i) {
    Body b{.name = "box " + std::to_string(i), .parts = {}, .color = {}};
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.0, i % 2 == 0 ? -0.5 : 0.5, 0.0) +
                         Eigen::Vector3d(static_cast<double>(i / 2) - 9.5, 0.0, 0.0) * 2.0;
    b.parts.push_back({Box{Eigen::Vector3d(0.5, 0.5, 0.5)}, pose});
    scene.obstacles.push_back(std::move(b));
  }
  CollisionChecker linear(scene), tree(scene);
  linear.use_broad_phase(BroadPhase::linear);
  tree.use_broad_phase(BroadPhase::tree);
  Scene odd_boxes = scene;  // the later box of each pair alone
  std::erase_if(odd_boxes.obstacles,
                [](const Body& b) { return b.parts[0].pose.translation().y() < 0.0; });
  CollisionChecker odd(odd_boxes);
  int ties = 0;
  for (int i = 0; i < 20; ++i) {
    Config q;
    q.t = Eigen::Vector3d(2.0 * (i - 9.5), 0.0, 0.0);
    const NearestObstacle a = linear.nearest_obstacle(q), b = tree.nearest_obstacle(q);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.obstacle, b.obstacle);
    EXPECT_EQ(a.obstacle % 2, 0u);  // of the two, the first
    ties += odd.nearest_obstacle(q).distance == a.distance ? 1 : 0;
  }
  EXPECT_EQ(ties, 20);
}

TEST(BroadPhase, AutomaticTakesTheTreeForManyParts) {
  const Problem few = box_field_problem({.parts = CollisionChecker::kBroadPhaseFrom - 1});
  const Problem many = box_field_problem({.parts = CollisionChecker::kBroadPhaseFrom});
  EXPECT_FALSE(CollisionChecker(few.scene).uses_tree());
  CollisionChecker checker(many.scene);
  EXPECT_TRUE(checker.uses_tree());
  checker.use_broad_phase(BroadPhase::linear);
  EXPECT_FALSE(checker.clone().uses_tree());
}

TEST(BoxField, NPartsAtConstantFillWithAFreeStartAndGoal) {
  for (const std::size_t parts : {std::size_t{10}, std::size_t{1000}}) {
    const Problem p = box_field_problem({.parts = parts, .seed = 3});
    EXPECT_EQ(p.scene.obstacles.size(), parts);
    CollisionChecker checker(p.scene);
    EXPECT_TRUE(checker.is_collision_free(p.start));
    EXPECT_TRUE(checker.is_collision_free(p.goal));
    EXPECT_TRUE(p.space.bounds().contains(p.start.t));
    EXPECT_TRUE(p.space.bounds().contains(p.goal.t));
    // The same seed, the same scene.
    const Problem again = box_field_problem({.parts = parts, .seed = 3});
    EXPECT_TRUE(again.scene.obstacles.back().parts[0].pose.isApprox(
        p.scene.obstacles.back().parts[0].pose, 0.0));
  }
  EXPECT_THROW(box_field_problem({.parts = 0}), InputError);
  EXPECT_THROW(box_field_problem({.parts = 5, .fill = 0.9}), InputError);
}

}  // namespace
}  // namespace tandem

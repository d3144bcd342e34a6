// The distance-grid pre-filter held against FCL: it may leave a query to FCL, never answer one
// wrongly. On random configurations of every shipped problem and a hair either side of contact,
// and on a part inside a solid box.

#include "tandem/collision/distance_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

TEST(DistanceGrid, IsALowerBoundOnTheDistanceToATriangle) {
  const DistanceGrid::Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0.3}};
  const DistanceGrid grid({{-1, -1, -1}, {2, 2, 2}}, 0.05, {t}, {});
  Rng rng(3);
  int near = 0, informative = 0;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3d p(rng.uniform(-1, 2), rng.uniform(-1, 2), rng.uniform(-1, 2));
    // The true distance, by dense sampling of the triangle (an upper bound on it, so the grid's
    // bound must stay below this too).
    double d = INFINITY;
    for (int a = 0; a <= 60; ++a) {
      for (int b = 0; a + b <= 60; ++b)
        d = std::min(d, (p - (t.a + (t.b - t.a) * a / 60.0 + (t.c - t.a) * b / 60.0)).norm());
    }
    const double lb = grid.lower_bound(p);
    EXPECT_LE(lb, d) << p.transpose();
    // Within five cells of the truth, where the grid stores distances (up to 32 cells).
    if (d < 1.4) {
      ++near;
      informative += lb > d - 0.25 ? 1 : 0;
    }
  }
  EXPECT_GT(near, 1000);
  EXPECT_EQ(informative, near) << "the bound is too loose to be of use";
}

TEST(DistanceGrid, APartInsideASolidBoxIsNeverCertifiedFree) {
  Scene scene;
  scene.object.name = "cube";
  scene.object.parts.push_back({Box{{0.2, 0.2, 0.2}}, Eigen::Isometry3d::Identity()});
  scene.obstacles.push_back(test::box_body("block", {4.0, 4.0, 4.0}, {0.0, 0.0, 0.0}));
  CollisionChecker checker(scene);
  checker.use_distance_grid({{-5, -5, -5}, {5, 5, 5}}, 0.1);
  ASSERT_TRUE(checker.has_distance_grid());
  EXPECT_FALSE(checker.is_collision_free(test::at(0.0, 0.0)));
  EXPECT_LE(checker.clearance_bound(test::at(0.0, 0.0), 1.0), 0.0);
  // Far outside the block the grid answers alone.
  checker.reset_counters();
  EXPECT_TRUE(checker.is_collision_free(test::at(4.5, 4.5)));
  EXPECT_EQ(checker.counters().prefilter_answers, 1u);
}

TEST(DistanceGrid, NeverDecidesWronglyOnEveryShippedProblem) {
  std::uint64_t answered = 0, asked = 0, opened = 0;
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    CollisionChecker fcl(p.scene);
    CollisionChecker gridded(p.scene);
    gridded.use_distance_grid(p.space.bounds(), 0.5 * p.space.translation_step());
    Rng rng(5);
    const double cap = 10.0 * p.space.translation_step();
    // Uniform samples, and configurations a hair either side of contact.
    std::vector<Config> configs = test::near_contact_configs(p, 7, 40);
    for (int i = 0; i < 400; ++i)
      configs.push_back(p.space.sample_uniform(rng));
    for (const Config& q : configs) {
      const NearestObstacle exact = fcl.nearest_obstacle(q);
      const bool free = fcl.is_collision_free(q);
      EXPECT_EQ(gridded.is_collision_free(q), free);
      const double bound = gridded.clearance_bound(q, cap, 0.25 * p.space.translation_step());
      EXPECT_LE(bound, cap);
      if (free)
        EXPECT_LE(bound, exact.distance + 1e-9 * p.space.translation_extent());
      else
        EXPECT_LE(bound, 0.0);
    }
    answered += gridded.counters().prefilter_answers;
    opened += gridded.counters().spheres_opened;
    asked += 2 * configs.size();
    RecordProperty(name + ": answered by the grid alone",
                   std::to_string(gridded.counters().prefilter_answers));
  }
  // The grid is not idle: it answers a share of the queries alone (14% of them on the built-in
  // scenes, which are all there is without ../shared).
  EXPECT_GT(answered, asked / 20);
  // Its work is counted (query_work()): spheres opened, at most its budget of 64 a query.
  EXPECT_GT(opened, 0u);
  EXPECT_LE(opened, 64u * asked);
}

}  // namespace
}  // namespace tandem

// The built-in scenes: they load, their starts and goals are valid, and each is solvable (a shipped
// path proves it).

#include "tandem/scene/builtin_scenes.hpp"

#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

TEST(BuiltinScenes, AllLoadWithValidStartAndGoal) {
  ASSERT_FALSE(builtin_scenes().empty());
  for (const auto& scene : builtin_scenes()) {
    const Problem p = load_problem(std::string(scene.name));
    CollisionChecker checker(p.scene);
    MotionValidator validator(p.space, checker);
    EXPECT_TRUE(validator.is_valid(p.start)) << scene.name;
    EXPECT_TRUE(validator.is_valid(p.goal)) << scene.name;
  }
}

TEST(ClutteredEnvironment1, MatchesThePapersDescription) {
  const Problem p = load_problem("cluttered-1");
  // The L-shaped part: 1.6 m long, 0.8 m high, 0.4 m wide.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const auto& part : p.scene.object.parts) {
    const Eigen::Vector3d half = 0.5 * std::get<Box>(part.geometry).size;
    lo = lo.cwiseMin(part.pose.translation() - half);
    hi = hi.cwiseMax(part.pose.translation() + half);
  }
  EXPECT_TRUE((hi - lo).isApprox(Eigen::Vector3d(1.6, 0.4, 0.8)));
  // Two walls 1.2 m apart, then two walls 0.75 m apart.
  auto inner_gap = [&](const std::string& a, const std::string& b) {
    double ya = 0, yb = 0;
    for (const auto& o : p.scene.obstacles) {
      const double half = 0.5 * std::get<Box>(o.parts[0].geometry).size.y();
      if (o.name == a)
        ya = o.parts[0].pose.translation().y() - half;
      if (o.name == b)
        yb = o.parts[0].pose.translation().y() + half;
    }
    return ya - yb;
  };
  EXPECT_NEAR(inner_gap("blue-wall-left", "blue-wall-right"), 1.2, 1e-12);
  EXPECT_NEAR(inner_gap("red-wall-left", "red-wall-right"), 0.75, 1e-12);
}

TEST(BuiltinScenes, EachIsSolvedByItsHandMadePathAndHasAGuide) {
  for (const auto& scene : builtin_scenes()) {
    const std::string name(scene.name);
    const Problem p = load_problem(name);
    const Path path = read_path_file(test::source_dir() / "scenes" / (name + ".path"), p.space);
    CollisionChecker checker(p.scene);
    MotionValidator validator(p.space, checker);
    const PathCheck check = check_path(path, validator);
    EXPECT_TRUE(check.valid) << name << ": " << check.describe();
    EXPECT_LT(p.space.distance(path.front(), p.start), 1e-5) << name;
    EXPECT_LT(p.space.distance(path.back(), p.goal), 1e-5) << name;
    // The simulated operators' guide: a gesture from the start to the goal, not a path.
    ASSERT_GE(p.guide.size(), 2u) << name;
    EXPECT_LE(p.guide.size(), kMaxGuideKeyframes) << name;
    EXPECT_LT(p.space.distance(p.guide.front(), p.start), 1e-9) << name;
    EXPECT_LT(p.space.distance(p.guide.back(), p.goal), 1e-9) << name;
  }
}

TEST(BuiltinScenes, ThePapersScenesAreAllThere) {
  for (const char* name : {"cluttered-1", "cluttered-2", "maze", "labyrinth-2d"})
    EXPECT_NO_THROW((void)load_problem(name)) << name;
  EXPECT_TRUE(load_problem("labyrinth-2d").space.planar());
}

TEST(ClutteredEnvironment1, ThePartSlidesUnderTheObliqueBarsLowEnd) {
  // With its leg under the bar's low end (x 4.35 to 4.6), the part fits on the floor but not 10 cm
  // up.
  const Problem p = load_problem("cluttered-1");
  CollisionChecker checker(p.scene);
  Config q = p.goal;
  q.t.x() = 3.8;
  EXPECT_TRUE(checker.is_collision_free(q));
  q.t.z() += 0.1;
  EXPECT_FALSE(checker.is_collision_free(q));
  EXPECT_EQ(checker.obstacle_name(checker.nearest_obstacle(q).obstacle), "oblique-bar");
}

}  // namespace
}  // namespace tandem

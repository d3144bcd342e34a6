// Passage islands on bugtrap, whose funnel admits the rod only along its axis: islands are made
// through the funnel's tip, and every configuration and motion of every island is valid as a
// fresh exact validator checks it. Without a distance grid there are none.

#include "tandem/planning/passage_islands.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "support/test_support.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/scene/ompl_app_problem.hpp"

namespace tandem {
namespace {

Problem bugtrap() {
  return load_ompl_app_problem(test::shared_dir() / "benchmarks" / "omplapp" / "3D" /
                               "bugtrap.cfg");
}

/// An island whose chain runs through the funnel's tip: the rod's reference point on the funnel's
/// axis (x = 16.5, z = 0) from inside the trap (y > 0) to below the tip's tube (y < -6).
bool through_the_tip(const Island& island) {
  double lo = 1e9, hi = -1e9;
  for (const Config& q : island.chain) {
    if (std::abs(q.t.x() - 16.5) > 1.0 || std::abs(q.t.z()) > 1.0)
      return false;
    lo = std::min(lo, q.t.y());
    hi = std::max(hi, q.t.y());
  }
  return lo < -6.0 && hi > 0.0;
}

TEST(PassageIslands, BugtrapsIslandsAreValidAndSomeGoThroughTheTip) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem problem = bugtrap();
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  validator.configure({MotionValidation::exact, 0.0, true});
  PassageIslands islands(validator, 7);
  // Islands are made until one goes through the tip (the narrowest band holds few of them).
  const auto any_through = [&] {
    for (std::size_t i = 0; i < islands.size(); ++i) {
      if (through_the_tip(islands.island(i)))
        return true;
    }
    return false;
  };
  for (int i = 0; i < 4000 && (i % 100 != 0 || !any_through()); ++i)
    islands.next_target(i % 2);
  ASSERT_GT(islands.passage_count(), 0u);
  ASSERT_GT(islands.size(), 0u);

  CollisionChecker fresh_checker(problem.scene);
  MotionValidator fresh(problem.space, fresh_checker);
  fresh.configure({MotionValidation::exact, 0.0, false});
  int through = 0;
  for (std::size_t i = 0; i < islands.size(); ++i) {
    const Island& island = islands.island(i);
    ASSERT_FALSE(island.chain.empty());
    for (std::size_t k = 0; k < island.chain.size(); ++k) {
      EXPECT_TRUE(fresh.is_valid(island.chain[k])) << "island " << i << " state " << k;
      if (k > 0) {
        EXPECT_TRUE(fresh.check_motion(island.chain[k - 1], island.chain[k]))
            << "island " << i << " motion " << k;
      }
    }
    through += through_the_tip(island) ? 1 : 0;
  }
  EXPECT_GT(through, 0) << "no island of " << islands.size() << " through the funnel's tip";
}

TEST(PassageIslands, NoneWithoutADistanceGrid) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem problem = bugtrap();
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  validator.configure({MotionValidation::exact, 0.0, false});
  PassageIslands islands(validator, 7);
  EXPECT_FALSE(islands.next_target(0).has_value());
  EXPECT_TRUE(islands.without_passages());
}

}  // namespace
}  // namespace tandem

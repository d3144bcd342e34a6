// Exact (continuous) motion validation: clearance bounds held against FCL's own collision and
// distance answers, a thin wall that the discrete check steps over, and random motions on every
// shipped problem that the exact check never accepts where a 100x finer discrete check finds a
// collision; the same checks asked in rounds with a helper thread.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "support/test_support.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validator.hpp"
#include "tandem/core/error.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

using test::at;

constexpr ValidationSettings kExact{MotionValidation::exact, 0.0};
constexpr ValidationSettings kDiscrete{MotionValidation::discrete, 0.0};

/// A 0.2 m cube and a 2 cm wall at x = 0 in a room so large that one discrete step (1% of its
/// diagonal) is 1.4 m: the discrete check of a 1.2 m motion looks at its end only.
Problem thin_wall_problem() {
  Scene scene;
  scene.object.name = "cube";
  scene.object.parts.push_back({Box{{0.2, 0.2, 0.2}}, Eigen::Isometry3d::Identity()});
  scene.obstacles.push_back(test::box_body("wall", {0.02, 100.0, 10.0}, {0.0, 0.0, 0.0}));
  Bounds bounds{{-50, -50, -5}, {50, 50, 5}};
  return Problem{"thin-wall",
                 "test",
                 std::move(scene),
                 SE3Space(SpaceKind::se3, bounds),
                 at(-0.6, 0),
                 at(0.6, 0),
                 {},
                 {},
                 std::nullopt};
}

TEST(ExactMotion, CatchesTheThinWallTheDiscreteCheckStepsOver) {
  const Problem p = thin_wall_problem();
  CollisionChecker checker(p.scene);
  MotionValidator discrete(p.space, checker, kDiscrete);
  MotionValidator exact(p.space, checker, kExact);
  ASSERT_EQ(p.space.segment_count(p.start, p.goal), 1u);
  EXPECT_TRUE(discrete.check_motion(p.start, p.goal));
  EXPECT_FALSE(exact.check_motion(p.start, p.goal));
  EXPECT_FALSE(exact.check_motion(p.goal, p.start));
  // With the wall moved out of the way the same motion is certified, with a few queries.
  Problem open = thin_wall_problem();
  open.scene.obstacles[0] = test::box_body("wall", {0.02, 1.0, 1.0}, {0.0, 0.0, -3.0});
  CollisionChecker open_checker(open.scene);
  MotionValidator open_exact(open.space, open_checker, kExact);
  EXPECT_TRUE(open_exact.check_motion(open.start, open.goal));
  EXPECT_LE(open_exact.checks(), 3u);
}

TEST(ExactMotion, InRoundsCatchesTheThinWallWhereverTheMotionsMiddleIs) {
  const Problem p = thin_wall_problem();
  CollisionChecker checker(p.scene);
  MotionValidator helped(p.space, checker, kExact);
  helped.use_helper_thread();
  // The wall at x = 0: through it from farther and farther away, the middle (asked with the ends)
  // certifies a stretch that stops short of it; in front of it, the whole motion is free.
  for (double x : {-0.6, -1.0, -1.5, -2.0, -3.0, -4.5}) {
    SCOPED_TRACE(x);
    EXPECT_FALSE(helped.check_motion(at(x, 0), at(0.6, 0)));
    EXPECT_FALSE(helped.check_motion(at(0.6, 0), at(x, 0)));
    EXPECT_TRUE(helped.check_motion(at(x, 0), at(-0.15, 0)));
  }
}

TEST(ExactMotion, TurningIsBoundedByTheObjectsRadius) {
  // A 1 m bar turning a quarter turn about z beside a post 0.45 m from its centre: every turn
  // sweeps the post, whatever the discrete steps see.
  Scene scene;
  scene.object.name = "bar";
  scene.object.parts.push_back({Box{{1.0, 0.05, 0.05}}, Eigen::Isometry3d::Identity()});
  scene.obstacles.push_back(test::box_body("post", {0.01, 0.01, 1.0}, {0.32, 0.32, 0.0}));
  const Problem p{"post",
                  "test",
                  std::move(scene),
                  SE3Space(SpaceKind::se3, Bounds{{-2, -2, -1}, {2, 2, 1}}),
                  at(0, 0),
                  at(0, 0),
                  {},
                  {},
                  std::nullopt};
  CollisionChecker checker(p.scene);
  EXPECT_NEAR(checker.object_radius(), std::sqrt(0.25 + 2 * 0.025 * 0.025), 1e-12);
  MotionValidator exact(p.space, checker, kExact);
  const Config start = at(0, 0, 0, 0.0), quarter = at(0, 0, 0, 1.5707963267948966);
  EXPECT_TRUE(exact.is_valid(start));
  EXPECT_TRUE(exact.is_valid(quarter));
  EXPECT_FALSE(exact.check_motion(start, quarter));
  const MotionCheck last = exact.check_motion_last_valid(start, quarter);
  EXPECT_FALSE(last.valid);
  EXPECT_TRUE(exact.check_motion(start, last.last_valid));
}

TEST(ExactMotion, ContactCloserThanTheToleranceIsInvalid) {
  const Problem p = thin_wall_problem();
  CollisionChecker checker(p.scene);
  MotionValidator exact(p.space, checker, {MotionValidation::exact, 0.01});
  // The cube's face at x + 0.1, the wall's at -0.01. The bound may be short of the distance by
  // the factor 1 + kClearanceRelativeError, so 1.3 cm away is surely valid, 0.5 cm surely not.
  EXPECT_TRUE(exact.is_valid(at(-0.11 - 0.013, 0)));
  EXPECT_FALSE(exact.is_valid(at(-0.11 - 0.005, 0)));
  EXPECT_FALSE(exact.is_valid(at(0, 0)));
  const ValidationSettings nan_tolerance{MotionValidation::exact, std::nan("")};
  EXPECT_THROW(exact.configure(nan_tolerance), InputError);
}

// The bounds of meshes come from tandem's own search of FCL's OBB trees (mesh_proximity.hpp);
// the reference is FCL's exact distance on its OBBRSS trees (nearest_obstacle). Uniform states with
// caps up to a fifth of the bounds, and states a hair either side of contact with caps around the
// quarter resolution step the exact validation asks FCL for.
TEST(ExactMotion, ClearanceBoundsNeverExceedFclsDistanceOnEveryShippedProblem) {
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    CollisionChecker checker(p.scene);
    const double slack = 1e-9 * p.space.translation_extent();
    const double grow = 1.0 + CollisionChecker::kClearanceRelativeError;
    Rng rng(7);
    std::vector<std::pair<Config, double>> cases;
    for (int i = 0; i < 200; ++i) {
      Config q = p.space.sample_uniform(rng);
      cases.emplace_back(std::move(q), rng.uniform(0.0, 0.2) * p.space.translation_extent());
    }
    for (Config& q : test::near_contact_configs(p, 23, 40))
      cases.emplace_back(std::move(q), rng.uniform(0.05, 1.0) * p.space.translation_step());
    int free = 0, below_cap = 0;
    for (const auto& [q, cap] : cases) {
      const NearestObstacle exact = checker.nearest_obstacle(q);
      const double bound = checker.clearance_bound(q, cap);
      EXPECT_LE(bound, cap);
      if (!checker.is_collision_free(q)) {
        EXPECT_LE(bound, 0.0);
        continue;
      }
      ++free;
      below_cap += bound < cap ? 1 : 0;
      EXPECT_LE(bound, exact.distance + slack);
      // And it is no looser than FCL's relative error allows.
      EXPECT_GE(bound, std::min(cap, exact.distance / grow) - slack);
    }
    EXPECT_GT(free, 0);
    EXPECT_GT(below_cap, 0);  // some bounds came from a distance found, not the cap
  }
}

TEST(ExactMotion, AStateFartherThanTheCapIsBoundedByTheCapItselfNotARoundingBelow) {
  // A bound capped at c for a state farther than c is c exactly: the validator's is_valid asks
  // for the tolerance and compares with it. (c (1 + e)) / (1 + e) rounded below c for some c, so
  // free states read as in contact and a planner's path failed its own check.
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    CollisionChecker checker(p.scene);
    Rng rng(11);
    int tried = 0;
    for (int i = 0; i < 200; ++i) {
      const Config q = p.space.sample_uniform(rng);
      const double cap =
          std::exp(rng.uniform(std::log(1e-8), std::log(1e-3))) * p.space.translation_extent();
      if (!(checker.nearest_obstacle(q).distance > 2.0 * cap))
        continue;
      ++tried;
      EXPECT_GE(checker.clearance_bound(q, cap, cap), cap) << "cap " << cap;
    }
    EXPECT_GT(tried, 0);
  }
}

/// Whether the motion collides at any of n equal steps (FCL's yes/no answer).
bool collides_finely(const SE3Space& space, CollisionChecker& checker, const Config& a,
                     const Config& b, unsigned n) {
  for (unsigned k = 0; k <= n; ++k) {
    if (!checker.is_collision_free(space.interpolate(a, b, static_cast<double>(k) / n)))
      return true;
  }
  return false;
}

TEST(ExactMotion, NeverAcceptsAMotionThatAHundredTimesFinerDiscreteCheckRejects) {
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    CollisionChecker checker(p.scene);
    MotionValidator exact(p.space, checker, kExact);
    MotionValidator discrete(p.space, checker, kDiscrete);
    Rng rng(11);
    int accepted = 0, discrete_only = 0, tried = 0;
    for (int attempts = 0; tried < 300 && attempts < 20000; ++attempts) {
      const Config a = p.space.sample_uniform(rng);
      if (!exact.is_valid(a))
        continue;
      // A motion of up to a tenth of the space's extent, half of them longer than a step.
      Config b = p.space.interpolate(a, p.space.sample_uniform(rng), rng.uniform(0.0, 0.1));
      ++tried;
      const bool ok = exact.check_motion(a, b);
      const unsigned n = std::max(1u, p.space.segment_count(a, b)) * 100;
      if (ok) {
        ++accepted;
        EXPECT_FALSE(collides_finely(p.space, checker, a, b, n));
        EXPECT_TRUE(exact.check_motion(b, a));
      } else if (discrete.check_motion(a, b)) {
        ++discrete_only;
      }
    }
    EXPECT_EQ(tried, 300);
    EXPECT_GT(accepted, 30) << "too few motions accepted for the test to mean something";
    RecordProperty(name + ": discrete accepts, exact refuses", discrete_only);
  }
}

/// The checks' answers of `v` to `motions`, in order.
std::vector<bool> answers(MotionValidator& v,
                          const std::vector<std::pair<Config, Config>>& motions) {
  std::vector<bool> out;
  for (const auto& [a, b] : motions)
    out.push_back(v.check_motion(a, b));
  return out;
}

TEST(ExactMotion, InRoundsWithAHelperThreadTheAnswersAreTheSameAndSoIsTheWork) {
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    CollisionChecker checker(p.scene);
    MotionValidator alone(p.space, checker, kExact);
    Rng rng(5);
    std::vector<std::pair<Config, Config>> motions;
    while (motions.size() < 300) {
      const Config a = p.space.sample_uniform(rng);
      if (alone.is_valid(a))
        motions.emplace_back(
            a, p.space.interpolate(a, p.space.sample_uniform(rng), rng.uniform(0.0, 0.5)));
    }
    const std::vector<bool> expected = answers(alone, motions);
    const auto valid = std::ranges::count(expected, true);
    EXPECT_GT(valid, 20) << "too few valid motions for the test to mean something";
    EXPECT_GT(std::ssize(expected) - valid, 20) << "too few invalid ones";
    // Two validators with helpers, each on a checker of its own: the same answers as alone, and
    // the same queries and work as each other, whichever thread answered which query.
    std::vector<std::uint64_t> checks, work;
    for (int k = 0; k < 2; ++k) {
      CollisionChecker own = checker.clone();
      MotionValidator helped(p.space, own, kExact);
      helped.use_helper_thread();
      EXPECT_EQ(answers(helped, motions), expected);
      checks.push_back(helped.checks());
      work.push_back(helped.work());
      EXPECT_GT(own.counters().clearance_queries, 0u);
    }
    EXPECT_EQ(checks[0], checks[1]);
    EXPECT_EQ(work[0], work[1]);
  }
}

TEST(ExactMotion, TheLastValidConfigurationIsReachedByAValidMotion) {
  for (const char* name : {"cluttered-1", "maze"}) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    CollisionChecker checker(p.scene);
    MotionValidator exact(p.space, checker, kExact);
    Rng rng(3);
    int stopped = 0;
    for (int i = 0; i < 300; ++i) {
      const Config a = p.space.sample_uniform(rng);
      if (!exact.is_valid(a))
        continue;
      const Config b = p.space.sample_uniform(rng);
      const MotionCheck r = exact.check_motion_last_valid(a, b);
      EXPECT_TRUE(exact.is_valid(r.last_valid));
      if (r.valid)
        continue;
      if (r.last_valid_step > 0) {
        ++stopped;
        EXPECT_TRUE(exact.check_motion(a, r.last_valid));
      }
    }
    EXPECT_GT(stopped, 5);
  }
}

// A short motion needs a small clearance, and the sweep's bound was asked for no more: read as
// closer than its stopping distance, every short motion was refused (in a live session, the
// operator's small moves never added a node).
TEST(ExactMotion, AShortMotionInTheOpenIsValidForTheLastValidSweepToo) {
  const Problem p = test::wall_with_gap_problem();
  CollisionChecker checker(p.scene);
  MotionValidator exact(p.space, checker, kExact);
  for (const double length : {1e-7, 1e-5, 1e-3, 0.1}) {
    SCOPED_TRACE(length);
    const Config a = at(-2, 0), b = at(-2 + length, 0);
    EXPECT_TRUE(exact.check_motion(a, b));
    const MotionCheck r = exact.check_motion_last_valid(a, b);
    EXPECT_TRUE(r.valid);
    EXPECT_EQ(r.last_valid, b);
  }
}

}  // namespace
}  // namespace tandem

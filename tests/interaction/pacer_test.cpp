// How a simulated operator keeps pace with the roadmap it watches.

#include "tandem/interaction/pacer.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace tandem {
namespace {

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

TEST(Pacer, APersonNoticesTheRoadmapLateAndCountsTheTimeSpentGoingBack) {
  Pacer p(1.0, 0.25);
  EXPECT_EQ(p.advance(1.0, 0.0), 1.0);
  // The roadmap falls behind at 1.1 s; the person notices at 1.35 s and only then goes back.
  EXPECT_EQ(p.advance(1.1, 5.0), 1.1);
  EXPECT_EQ(p.advance(1.3, 5.0), 1.3);
  EXPECT_NEAR(p.advance(1.4, 5.0), 1.2, 1e-12);
  EXPECT_NEAR(p.waited(), 0.1, 1e-12);
  // The roadmap catches up at 1.5 s: the person goes on going back until 1.75 s.
  EXPECT_NEAR(p.advance(1.5, 0.0), 1.1, 1e-12);
  EXPECT_NEAR(p.advance(1.7, 0.0), 0.9, 1e-12);
  EXPECT_NEAR(p.advance(1.8, 0.0), 1.0, 1e-12);
  EXPECT_NEAR(p.waited(), 0.4, 1e-12);
  EXPECT_EQ(p.waits(), 3u);

  Pacer at_once(1.0);  // no delay: as before
  EXPECT_EQ(at_once.advance(1.0, 5.0), 0.0);
  EXPECT_NEAR(at_once.waited(), 1.0, 1e-12);
}

}  // namespace
}  // namespace tandem

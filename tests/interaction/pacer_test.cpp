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

}  // namespace
}  // namespace tandem

// Workspace passages on the distance grid: a square tube's axis is found, along the tube; a flat
// wall and a wide tube have none.

#include "tandem/collision/passages.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tandem {
namespace {

/// A square tube along z: four walls 0.2 thick whose inner faces are `half` from the axis, from
/// z = -2 to 2.
std::vector<DistanceGrid::Box> square_tube(double half) {
  const double o = half + 0.2;
  return {{{half, -o, -2}, {o, o, 2}},
          {{-o, -o, -2}, {-half, o, 2}},
          {{-half, half, -2}, {half, o, 2}},
          {{-half, -o, -2}, {half, -half, 2}}};
}

TEST(Passages, ASquareTubesAxisIsFoundAlongTheTube) {
  const DistanceGrid grid({{-3, -3, -3}, {3, 3, 3}}, 0.1, {}, square_tube(0.6));
  const std::vector<Passage> passages = find_passages(grid, 2.0);
  int inside = 0;
  for (const Passage& p : passages) {
    if (std::abs(p.point.z()) > 1.0 || std::abs(p.point.x()) > 0.6 || std::abs(p.point.y()) > 0.6)
      continue;
    ++inside;
    // On the axis or on the diagonals near it (a square's medial axis is its diagonals): at
    // most 0.4 of the 0.6 to the walls, never near them.
    EXPECT_LT(std::abs(p.point.x()), 0.4) << p.point.transpose();
    EXPECT_LT(std::abs(p.point.y()), 0.4) << p.point.transpose();
    EXPECT_GT(std::abs(p.direction.z()), 0.95) << p.direction.transpose();
    EXPECT_NEAR(p.direction.norm(), 1.0, 1e-9);
    EXPECT_LE(p.clearance, 0.6);
    EXPECT_GT(p.clearance, 0.0);
  }
  EXPECT_GE(inside, 15) << "the axis runs 2 units (away from the ends) through cells of 0.1";
}

TEST(Passages, OnlyTubesNarrowerThanTheLimitCount) {
  const DistanceGrid grid({{-3, -3, -3}, {3, 3, 3}}, 0.1, {}, square_tube(0.6));
  for (const Passage& p : find_passages(grid, 0.3))
    EXPECT_LT(p.clearance, 0.3);
  int inside = 0;
  for (const Passage& p : find_passages(grid, 0.3))
    inside += std::abs(p.point.x()) < 0.1 && std::abs(p.point.y()) < 0.1 ? 1 : 0;
  EXPECT_EQ(inside, 0) << "the tube's axis is 0.6 - 0.1 sqrt(3)/2 from its walls, as bounded";
}

TEST(Passages, AFlatWallHasNone) {
  const DistanceGrid grid({{-3, -3, -3}, {3, 3, 3}}, 0.1, {}, {{{-0.1, -3, -3}, {0.1, 3, 3}}});
  EXPECT_TRUE(find_passages(grid, 10.0).empty());
}

}  // namespace
}  // namespace tandem

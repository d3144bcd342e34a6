// The workspace guide on the distance grid: a route through a wall's hole, through the wider of
// two holes, none through a closed wall, and none over a wall's top when the bounds leave no room;
// the blocks' neighbours are the 26 around each block that the coarse grid holds, in z, y, x order.

#include "tandem/collision/workspace_guide.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <random>
#include <utility>
#include <vector>

namespace tandem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A wall across the whole grid at z = 0 (0.2 thick), with a square hole of half width `half`
/// centred at (x, 0) for each x in `holes`.
std::vector<DistanceGrid::Box> wall(double half, const std::vector<double>& holes) {
  if (holes.empty())
    return {{{-5, -5, -0.1}, {5, 5, 0.1}}};
  std::vector<DistanceGrid::Box> boxes{{{-5, -5, -0.1}, {5, -half, 0.1}},
                                       {{-5, half, -0.1}, {5, 5, 0.1}}};
  double x0 = -5.0;
  for (double x : holes) {
    boxes.push_back({{x0, -half, -0.1}, {x - half, half, 0.1}});
    x0 = x + half;
  }
  boxes.push_back({{x0, -half, -0.1}, {5, half, 0.1}});
  return boxes;
}

const Bounds kBounds{{-3, -3, -3}, {3, 3, 3}};

/// The guide's points within 0.15 of the wall's plane.
std::vector<GuidePoint> at_the_wall(const std::vector<GuidePoint>& guide) {
  std::vector<GuidePoint> near;
  for (const GuidePoint& g : guide) {
    if (std::abs(g.point.z()) < 0.15)
      near.push_back(g);
  }
  return near;
}

TEST(WorkspaceGuide, TheRouteGoesThroughTheHole) {
  const DistanceGrid grid({kBounds.min, kBounds.max}, 0.05, {}, wall(0.4, {1.5}));
  const std::vector<GuidePoint> guide =
      find_guide(grid, GuideBlocks(grid, kBounds), {-1, 0, -2}, {-1, 0, 2}, 1.0);
  ASSERT_GE(guide.size(), 3u);
  EXPECT_TRUE(guide.front().point.isApprox(Eigen::Vector3d(-1, 0, -2)));
  EXPECT_TRUE(guide.back().point.isApprox(Eigen::Vector3d(-1, 0, 2)));
  const std::vector<GuidePoint> crossing = at_the_wall(guide);
  ASSERT_FALSE(crossing.empty()) << "a route from below the wall to above it crosses its plane";
  for (const GuidePoint& g : crossing) {
    EXPECT_NEAR(g.point.x(), 1.5, 0.4) << g.point.transpose();
    EXPECT_NEAR(g.point.y(), 0.0, 0.4) << g.point.transpose();
    EXPECT_GT(g.clearance, 0.0);
  }
  for (std::size_t k = 1; k + 1 < guide.size(); ++k)
    EXPECT_TRUE(kBounds.contains(guide[k].point)) << guide[k].point.transpose();
}

TEST(WorkspaceGuide, TheWiderOfTwoHolesIsTaken) {
  // The narrow hole is right under the straight line; the wide one is 2 units aside.
  const DistanceGrid grid({kBounds.min, kBounds.max}, 0.05, {}, wall(0.0, {}));
  const DistanceGrid holes({kBounds.min, kBounds.max}, 0.05, {}, [] {
    std::vector<DistanceGrid::Box> b = {
        {{-5, -5, -0.1}, {5, -0.6, 0.1}},       // y < -0.6
        {{-5, 0.6, -0.1}, {5, 5, 0.1}},         // y > 0.6
        {{-5, -0.6, -0.1}, {-0.15, 0.6, 0.1}},  // narrow hole at x = 0
        {{0.15, -0.6, -0.1}, {1.4, 0.6, 0.1}},  // wide hole at x = 2
        {{2.6, -0.6, -0.1}, {5, 0.6, 0.1}}};
    return b;
  }());
  const std::vector<GuidePoint> guide =
      find_guide(holes, GuideBlocks(holes, kBounds), {0, 0, -2}, {0, 0, 2}, 1.0);
  const std::vector<GuidePoint> crossing = at_the_wall(guide);
  ASSERT_FALSE(crossing.empty());
  for (const GuidePoint& g : crossing)
    EXPECT_NEAR(g.point.x(), 2.0, 0.6) << g.point.transpose();
  EXPECT_TRUE(find_guide(grid, GuideBlocks(grid, kBounds), {0, 0, -2}, {0, 0, 2}, 1.0).empty())
      << "a closed wall leaves no route";
}

TEST(WorkspaceGuide, TheRouteStaysInTheBounds) {
  // A wall across x = 0 up to z = 1; above it there is room only if the bounds reach above 1.
  const std::vector<DistanceGrid::Box> low_wall = {{{-0.1, -5, -5}, {0.1, 5, 1}}};
  const DistanceGrid grid({kBounds.min, kBounds.max}, 0.05, {}, low_wall);
  const std::vector<GuidePoint> over =
      find_guide(grid, GuideBlocks(grid, kBounds), {-2, 0, 0}, {2, 0, 0}, 1.0);
  ASSERT_FALSE(over.empty());
  double highest = -10.0;
  for (const GuidePoint& g : over)
    highest = std::max(highest, g.point.z());
  EXPECT_GT(highest, 1.0) << "the route passes over the wall";
  const Bounds below{{-3, -3, -3}, {3, 3, 0.8}};
  EXPECT_TRUE(find_guide(grid, GuideBlocks(grid, below), {-2, 0, 0}, {2, 0, 0}, 1.0).empty());
}

/// Step 2 as written: the widest-first search with a heap, on the clearances themselves.
double reference_bottleneck(const GuideBlocks& b, int from, int to) {
  std::vector<double> width(static_cast<std::size_t>(b.size()), -kInf);
  std::priority_queue<std::pair<double, int>> open;
  width[static_cast<std::size_t>(from)] = kInf;
  open.push({kInf, from});
  while (!open.empty()) {
    const double w = open.top().first;
    const int i = open.top().second;
    open.pop();
    if (i == to)
      return w;
    if (w < width[static_cast<std::size_t>(i)])
      continue;
    b.for_neighbours(i, [&](int n) {
      if (n != to && !b.open(n))
        return;
      const double c = n == to ? w : std::min(w, b.clearance(n));
      if (c > width[static_cast<std::size_t>(n)]) {
        width[static_cast<std::size_t>(n)] = c;
        open.push({c, n});
      }
    });
  }
  return -kInf;
}

/// Step 3's cost of a move between neighbouring blocks.
double move_cost(const GuideBlocks& b, int i, int n, double open) {
  const double c = std::clamp(std::min(b.clearance(n), b.clearance(i)), 1e-3 * open, open);
  return (b.centre(n) - b.centre(i)).norm() * (1.0 + open / c);
}

/// Step 3 as written: Dijkstra's search over every block cheaper than the route.
double reference_cost(const GuideBlocks& b, int from, int to, double least, double open) {
  std::vector<double> cost(static_cast<std::size_t>(b.size()), kInf);
  std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>>
      queue;
  cost[static_cast<std::size_t>(from)] = 0.0;
  queue.push({0.0, from});
  while (!queue.empty()) {
    const double g = queue.top().first;
    const int i = queue.top().second;
    queue.pop();
    if (g > cost[static_cast<std::size_t>(i)])
      continue;
    b.for_neighbours(i, [&](int n) {
      if (n != to && (!b.open(n) || b.clearance(n) < least))
        return;
      const double next = g + move_cost(b, i, n, open);
      if (next < cost[static_cast<std::size_t>(n)]) {
        cost[static_cast<std::size_t>(n)] = next;
        queue.push({next, n});
      }
    });
  }
  return cost[static_cast<std::size_t>(to)];
}

TEST(WorkspaceGuide, TheRouteIsTheCheapestThroughBlocksHalfAsOpenAsTheBottleneck) {
  // Two holes of different widths in a wall, and a box in the way below it.
  std::vector<DistanceGrid::Box> boxes = wall(0.3, {-1.5, 1.0});
  boxes.push_back({{-0.5, -2.0, -1.6}, {2.0, 0.5, -1.0}});
  const DistanceGrid grid({kBounds.min, kBounds.max}, 0.05, {}, boxes);
  const GuideBlocks blocks(grid, kBounds);
  const double open = 0.5;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-2.9, 2.9);
  int routes = 0, through_the_wall = 0;
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d from(coordinate(rng), coordinate(rng), coordinate(rng));
    const Eigen::Vector3d to(coordinate(rng), coordinate(rng), coordinate(rng));
    const int first = blocks.block_of(grid, from);
    const int last = blocks.block_of(grid, to);
    const double width = reference_bottleneck(blocks, first, last);
    const std::vector<GuidePoint> guide = find_guide(grid, blocks, from, to, open);
    if (width == -kInf) {
      EXPECT_TRUE(guide.empty());
      continue;
    }
    const double least = std::isfinite(width) ? 0.5 * width : -width;
    ASSERT_GE(guide.size(), 2u);
    // The route's blocks: the ends' and those of the points between (each a block's centre).
    std::vector<int> route{first};
    for (std::size_t i = 1; i + 1 < guide.size(); ++i) {
      route.push_back(blocks.block_of(grid, guide[i].point));
      EXPECT_EQ(guide[i].clearance, blocks.clearance(route.back()));
      EXPECT_GE(guide[i].clearance, least);
    }
    route.push_back(last);
    double cost = 0.0;
    for (std::size_t i = 1; i < route.size(); ++i)
      cost += move_cost(blocks, route[i - 1], route[i], open);
    const double best = reference_cost(blocks, first, last, least, open);
    EXPECT_NEAR(cost, best, 1e-9 * best) << "from " << from.transpose() << " to " << to.transpose();
    ++routes;
    through_the_wall += (from.z() < -0.1) != (to.z() < -0.1) ? 1 : 0;
  }
  EXPECT_GT(routes, 50);
  EXPECT_GT(through_the_wall, 20) << "routes through a hole, where the bottleneck is narrow";
}

TEST(WorkspaceGuide, EachBlockVisitsTheNeighboursTheCoarseGridHoldsInZYXOrder) {
  // Narrower than long in each direction, so that inner blocks (the precomputed offsets) and every
  // kind of border block are visited.
  const Bounds bounds{{-1, -2, -3}, {1, 2, 3}};
  const DistanceGrid grid({bounds.min, bounds.max}, 0.05, {}, wall(0.4, {0.0}));
  const GuideBlocks blocks(grid, bounds);
  const Eigen::Vector3i d = blocks.dims();
  ASSERT_EQ(d.prod(), blocks.size());
  ASSERT_TRUE((d.array() >= 3).all()) << d.transpose();
  int inner = 0;
  for (int z = 0; z < d.z(); ++z) {
    for (int y = 0; y < d.y(); ++y) {
      for (int x = 0; x < d.x(); ++x) {
        std::vector<int> expected;
        for (int dz = -1; dz <= 1; ++dz) {
          for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = x + dx, ny = y + dy, nz = z + dz;
              if ((dx | dy | dz) != 0 && nx >= 0 && ny >= 0 && nz >= 0 && nx < d.x() &&
                  ny < d.y() && nz < d.z())
                expected.push_back((nz * d.y() + ny) * d.x() + nx);
            }
          }
        }
        std::vector<int> visited;
        blocks.for_neighbours((z * d.y() + y) * d.x() + x, [&](int n) { visited.push_back(n); });
        ASSERT_EQ(visited, expected) << "block " << x << ", " << y << ", " << z;
        inner += expected.size() == 26 ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(inner, (d.x() - 2) * (d.y() - 2) * (d.z() - 2));
}

}  // namespace
}  // namespace tandem

// The grid of boxes against a plain loop over them: every overlapping box visited exactly once and
// no other, on boxes of sizes over four decades, flat boxes, boxes whose faces lie on the cells'
// faces, queries outside the grid, covering it or not numbers at all; and the boxes a grid
// would serve badly refused.

#include "tandem/collision/box_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "tandem/core/rng.hpp"

namespace tandem {
namespace {

using Box = BoxGrid::Box;

bool overlaps(const Box& a, const Box& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

Eigen::Vector3d uniform(Rng& rng, double lo, double hi) {
  return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

/// A box at a uniform place in [lo, hi)³ with sides log-uniform in [small, large]; a side may be 0.
Box random_box(Rng& rng, double lo, double hi, double small, double large) {
  const Eigen::Vector3d min = uniform(rng, lo, hi);
  Eigen::Vector3d side;
  for (int a = 0; a < 3; ++a)
    side[a] = rng.below(10) == 0 ? 0.0 : small * std::pow(large / small, rng.uniform01());
  return {min, min + side};
}

/// Checks one query: every overlapping box once, no other; returns how many overlapped.
std::size_t expect_exact(const BoxGrid& grid, const std::vector<Box>& boxes, const Box& query) {
  std::map<std::size_t, int> visits;
  EXPECT_FALSE(grid.overlapping(query, [&](std::size_t i) {
    ++visits[i];
    return false;
  }));
  std::size_t expected = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const bool overlap = overlaps(boxes[i], query);
    expected += overlap ? 1 : 0;
    const int seen = visits.count(i) ? visits[i] : 0;
    EXPECT_EQ(seen, overlap ? 1 : 0) << "box " << i;
  }
  return expected;
}

TEST(BoxGrid, VisitsEveryOverlappingBoxOnceOnSpreadBoxesOfManySizes) {
  Rng rng(17);
  std::vector<Box> boxes;
  for (int i = 0; i < 3000; ++i)
    boxes.push_back(random_box(rng, -20.0, 20.0, 0.01, 2.0));
  for (int i = 0; i < 5; ++i)  // a few much larger than a cell
    boxes.push_back(random_box(rng, -25.0, 0.0, 10.0, 30.0));
  const auto grid = BoxGrid::build(boxes);
  ASSERT_TRUE(grid.has_value());
  EXPECT_GT(grid->large_count(), 0u);
  EXPECT_GT(grid->cell_count(), 1000u);
  std::size_t met = 0;
  for (int k = 0; k < 3000; ++k)
    met += expect_exact(*grid, boxes, random_box(rng, -22.0, 22.0, 0.001, 5.0));
  EXPECT_GT(met, 200u);  // the queries do meet boxes
  // Covering every cell (the scan), and outside the grid on every side.
  EXPECT_EQ(
      expect_exact(*grid, boxes, {Eigen::Vector3d::Constant(-100), Eigen::Vector3d::Constant(100)}),
      boxes.size());
  for (int a = 0; a < 3; ++a) {
    Box far{Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1)};
    far.min[a] = far.max[a] = 1e6;
    EXPECT_EQ(expect_exact(*grid, boxes, far), 0u);
    far.min[a] = far.max[a] = -1e6;
    EXPECT_EQ(expect_exact(*grid, boxes, far), 0u);
  }
}

TEST(BoxGrid, TouchingCountsWhereFacesLieOnTheCellsFaces) {
  // Unit cubes on an integer lattice: the cells are unit cubes too, so every face is a cell face.
  std::vector<Box> boxes;
  for (int x = 0; x < 12; x += 2)
    for (int y = 0; y < 12; y += 2)
      for (int z = 0; z < 12; z += 2)
        boxes.push_back({Eigen::Vector3d(x, y, z), Eigen::Vector3d(x + 1, y + 1, z + 1)});
  const auto grid = BoxGrid::build(boxes);
  ASSERT_TRUE(grid.has_value());
  Rng rng(5);
  for (int k = 0; k < 2000; ++k) {
    // Queries from lattice point to lattice point, half a unit, or a point.
    const Eigen::Vector3d min =
        Eigen::Vector3d(double(rng.below(26)), double(rng.below(26)), double(rng.below(26))) / 2.0 -
        Eigen::Vector3d::Constant(0.5);
    const Eigen::Vector3d side(double(rng.below(5)), double(rng.below(5)), double(rng.below(5)));
    expect_exact(*grid, boxes, {min, min + side / 2.0});
  }
  // A point on a shared corner of a cube touches it.
  EXPECT_EQ(expect_exact(*grid, boxes, {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, 1)}), 1u);
}

/// Fifty half-unit boxes in a row along x.
std::vector<Box> row_of_boxes() {
  std::vector<Box> boxes;
  for (int i = 0; i < 50; ++i)
    boxes.push_back({Eigen::Vector3d(i, 0, 0), Eigen::Vector3d(i + 0.5, 1, 1)});
  return boxes;
}

TEST(BoxGrid, StopsAtTheFirstVisitThatAsksTo) {
  const std::vector<Box> boxes = row_of_boxes();
  const auto grid = BoxGrid::build(boxes);
  ASSERT_TRUE(grid.has_value());
  for (const Box& query : {Box{Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(60, 2, 2)},
                           Box{Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(14, 1, 1)}}) {
    int visits = 0;
    EXPECT_TRUE(grid->overlapping(query, [&](std::size_t) { return ++visits == 2; }));
    EXPECT_EQ(visits, 2);
  }
}

TEST(BoxGrid, AQueryThatIsNotANumberMeetsNothing) {
  const std::vector<Box> boxes = row_of_boxes();
  const auto grid = BoxGrid::build(boxes);
  ASSERT_TRUE(grid.has_value());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expect_exact(*grid, boxes, {Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d(nan, 1, 1)}),
            0u);
}

TEST(BoxGrid, RefusesCrowdedUnboundedOrNotNumberBoxes) {
  Rng rng(3);
  std::vector<Box> piled;  // a thousand boxes in one place: every query would meet them all
  for (int i = 0; i < 1000; ++i)
    piled.push_back(random_box(rng, 0.0, 0.1, 0.5, 1.0));
  piled.push_back({Eigen::Vector3d::Constant(100), Eigen::Vector3d::Constant(101)});
  EXPECT_FALSE(BoxGrid::build(piled).has_value());
  std::vector<Box> large;  // more boxes much larger than a cell than a query should test
  for (int i = 0; i < 400; ++i)
    large.push_back(random_box(rng, 0.0, 100.0, 0.1, 0.2));
  for (int i = 0; i < 40; ++i)
    large.push_back(random_box(rng, 0.0, 10.0, 50.0, 60.0));
  EXPECT_FALSE(BoxGrid::build(large).has_value());
  EXPECT_FALSE(BoxGrid::build({}).has_value());
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(BoxGrid::build({{Eigen::Vector3d::Zero(), Eigen::Vector3d(inf, 1, 1)}}).has_value());
  const double nan = std::numeric_limits<double>::quiet_NaN(), huge = 1e308;
  EXPECT_FALSE(BoxGrid::build({{Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()},
                               {Eigen::Vector3d::Zero(), Eigen::Vector3d(nan, 1, 1)}})
                   .has_value());
  EXPECT_FALSE(BoxGrid::build({{Eigen::Vector3d::Constant(-huge), Eigen::Vector3d::Zero()},
                               {Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(huge)}})
                   .has_value());
}

}  // namespace
}  // namespace tandem

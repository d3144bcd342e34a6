#include "tandem/nn/kd_tree_nn.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "tandem/nn/linear_nn.hpp"

namespace tandem {
namespace {

/// Feeds the same points to the k-d tree and to brute force and compares their answers: the same
/// ids, ties going to the smaller id in both.
void expect_same_answers(const SE3Space& space, std::vector<Config>& points,
                         const std::vector<Config>& queries, std::size_t k) {
  KdTreeNearestNeighbors fast(space, points);
  LinearNearestNeighbors slow(space, points);
  for (NodeId i = 0; i < points.size(); ++i) {
    fast.add(i);
    slow.add(i);
  }
  ASSERT_EQ(fast.size(), points.size());
  std::vector<NodeId> a, b;
  for (const Config& q : queries) {
    ASSERT_EQ(space.distance(q, points[fast.nearest(q)]),
              space.distance(q, points[slow.nearest(q)]));
    fast.k_nearest(q, k, a);
    slow.k_nearest(q, k, b);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(space.distance(q, points[a[i]]), space.distance(q, points[b[i]])) << "rank " << i;
    }
  }
}

std::vector<Config> samples(const SE3Space& space, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Config> out;
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(space.sample_uniform(rng));
  return out;
}

TEST(KdTree, MatchesBruteForceOnUniformSE3Points) {
  const SE3Space space(SpaceKind::se3, Bounds{{-10, -10, -10}, {10, 10, 10}});
  auto points = samples(space, 5000, 1);
  expect_same_answers(space, points, samples(space, 500, 2), 10);
}

TEST(KdTree, MatchesBruteForceWhenRotationDominates) {
  // A small workspace and a heavy rotation weight: the translation lower bound prunes little, and
  // the search must still be exact.
  const SE3Space space(SpaceKind::se3, Bounds{{0, 0, 0}, {0.1, 0.1, 0.1}}, MetricWeights{1.0, 5.0});
  auto points = samples(space, 3000, 3);
  expect_same_answers(space, points, samples(space, 300, 4), 7);
}

TEST(KdTree, MatchesBruteForceInPlanarSpaces) {
  const SE3Space space(SpaceKind::planar, Bounds{{-50, -50, 0}, {50, 50, 0}});
  auto points = samples(space, 4000, 5);
  expect_same_answers(space, points, samples(space, 300, 6), 5);
}

TEST(KdTree, StaysExactAndShallowOnPointsAddedAlongALine) {
  // RRT-Connect adds long runs of nodes along straight motions.
  const SE3Space space(SpaceKind::se3, Bounds{{0, 0, 0}, {100, 1, 1}});
  std::vector<Config> points;
  for (int i = 0; i < 4000; ++i) {
    Config q;
    q.t = Eigen::Vector3d(i * 0.025, 0.5, 0.5);
    points.push_back(q);
  }
  expect_same_answers(space, points, samples(space, 200, 7), 4);
}

TEST(KdTree, HandlesManyPointsAtOnePosition) {
  const SE3Space space(SpaceKind::se3, Bounds{{0, 0, 0}, {1, 1, 1}});
  Rng rng(8);
  std::vector<Config> points;
  for (int i = 0; i < 500; ++i) {
    Config q = space.sample_uniform(rng);
    q.t = Eigen::Vector3d(0.5, 0.5, 0.5);
    points.push_back(q);
  }
  expect_same_answers(space, points, samples(space, 100, 9), 3);
}

TEST(KdTree, StaysExactWhenPointsDifferByTinyRotations) {
  // Points and queries at a few positions and orientations, each rotated by up to 1e-3 rad (down to
  // 1e-12): distances differ only in the rotation term, often by less than the cheap bound's
  // margin, where a bound that overshot would skip the nearest point.
  const SE3Space space(SpaceKind::se3, Bounds{{0, 0, 0}, {1, 1, 1}}, MetricWeights{1.0, 5.0});
  Rng rng(13);
  const auto bases = samples(space, 4, 14);
  auto jitter = [&](const Config& base) {
    Config q = base;
    const double angle = std::pow(10.0, -3.0 - 9.0 * rng.uniform01());
    const Eigen::Vector3d axis = space.sample_uniform(rng).t - Eigen::Vector3d::Constant(0.5);
    q.q = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized())) * base.q).normalized();
    return q;
  };
  std::vector<Config> points, queries;
  for (int i = 0; i < 3000; ++i)
    points.push_back(jitter(bases[static_cast<std::size_t>(i) % bases.size()]));
  for (int i = 0; i < 300; ++i)
    queries.push_back(jitter(bases[static_cast<std::size_t>(i) % bases.size()]));
  expect_same_answers(space, points, queries, 6);
}

TEST(KdTree, BreaksTiesByTheSmallerIdAsALinearScanDoes) {
  // A grid of positions, each with a few orientations given as q and as -q (one rotation), every
  // point added twice: queries at cell centres and at grid points are equidistant from many.
  const SE3Space space(SpaceKind::se3, Bounds{{0, 0, 0}, {4, 4, 4}});
  const auto turns = samples(space, 3, 15);
  std::vector<Config> points, queries;
  for (int x = 0; x < 5; ++x) {
    for (int y = 0; y < 5; ++y) {
      for (int z = 0; z < 5; ++z) {
        for (const Config& turn : turns) {
          Config c{Eigen::Vector3d(x, y, z), turn.q};
          points.push_back(c);
          c.q.coeffs() = -c.q.coeffs();
          points.push_back(c);
          points.push_back(c);
        }
        queries.push_back(Config{Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5), turns[0].q});
        queries.push_back(Config{Eigen::Vector3d(x, y, z), turns[1].q});
      }
    }
  }
  expect_same_answers(space, points, queries, 9);
}

TEST(KdTree, GrowsIncrementallyWhileQueried) {
  // Past two whole-tree rebuilds (at 4 096 and 8 192 points), queried around each.
  const SE3Space space(SpaceKind::se3, Bounds{{-1, -1, -1}, {1, 1, 1}});
  Rng rng(10);
  std::vector<Config> points;
  KdTreeNearestNeighbors fast(space, points);
  LinearNearestNeighbors slow(space, points);
  for (NodeId i = 0; i < 9000; ++i) {
    points.push_back(
        space.sample_uniform(rng));  // may reallocate: the index reads through the vector
    fast.add(i);
    slow.add(i);
    const NodeId from_rebuild = std::min(i % 4096, 4096 - i % 4096);
    if (i > 2000 && from_rebuild > 48 && i % 50 != 0)
      continue;
    const Config q = space.sample_uniform(rng);
    ASSERT_EQ(fast.nearest(q), slow.nearest(q));
  }
  fast.clear();
  EXPECT_EQ(fast.size(), 0u);
}

TEST(KdTree, KNearestReturnsAllWhenKExceedsSize) {
  const SE3Space space(SpaceKind::se3, Bounds{{-1, -1, -1}, {1, 1, 1}});
  auto points = samples(space, 5, 12);
  KdTreeNearestNeighbors fast(space, points);
  for (NodeId i = 0; i < 5; ++i)
    fast.add(i);
  std::vector<NodeId> out;
  fast.k_nearest(points[0], 10, out);
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[0], 0u);
}

}  // namespace
}  // namespace tandem

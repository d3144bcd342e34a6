// tandem's searches of FCL's OBB trees, held against FCL: the yes/no answers against fcl::collide
// on the same trees, the capped distance bounds against FCL's exact distance on OBBRSS trees of
// the same triangles (as fcl::distance with a default request computes it).

#include "tandem/collision/mesh_proximity.hpp"

#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "tandem/core/rng.hpp"
#include "tandem/space/config.hpp"

namespace tandem {
namespace {

struct Soup {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
};

/// n random triangles of sides up to 0.3 inside a unit cube: a deep tree with boxes of every shape.
Soup random_soup(Rng& rng, int n) {
  Soup s;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d c(rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0));
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back(c + 0.15 * Eigen::Vector3d(rng.uniform(-1.0, 1.0),
                                                      rng.uniform(-1.0, 1.0),
                                                      rng.uniform(-1.0, 1.0)));
    }
    const auto v = static_cast<std::size_t>(3 * i);
    s.triangles.emplace_back(v, v + 1, v + 2);
  }
  return s;
}

template <class BV>
std::shared_ptr<fcl::BVHModel<BV>> model(const Soup& s) {
  auto m = std::make_shared<fcl::BVHModel<BV>>();
  m->beginModel();
  m->addSubModel(s.vertices, s.triangles);
  m->endModel();
  return m;
}

Eigen::Isometry3d random_pose(Rng& rng, double reach) {
  Config q;
  q.t = Eigen::Vector3d(rng.uniform(-reach, reach), rng.uniform(-reach, reach),
                        rng.uniform(-reach, reach));
  q.q = Eigen::Quaterniond(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0),
                           rng.uniform(-1.0, 1.0))
            .normalized();
  return q.pose();
}

TEST(MeshProximity, AnswersAsFclAndBoundsItsExactDistanceWithinTheRelativeError) {
  Rng rng(5);
  const Soup a = random_soup(rng, 300);
  const Soup b = random_soup(rng, 200);
  const auto obb_a = model<fcl::OBBd>(a);
  const auto obb_b = model<fcl::OBBd>(b);
  const auto rss_a = model<fcl::OBBRSSd>(a);
  const auto rss_b = model<fcl::OBBRSSd>(b);
  int intersecting = 0, near = 0, beyond_cap = 0;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Isometry3d X_WA = random_pose(rng, 1.0);
    const Eigen::Isometry3d X_WB = random_pose(rng, 1.0);
    fcl::CollisionRequestd hit_request;
    fcl::CollisionResultd hit;
    const bool collide = fcl::collide(rss_a.get(), X_WA, rss_b.get(), X_WB, hit_request, hit) > 0;
    fcl::DistanceRequestd request;
    fcl::DistanceResultd result;
    fcl::distance(rss_a.get(), X_WA, rss_b.get(), X_WB, request, result);
    const double exact = collide ? 0.0 : result.min_distance;
    fcl::CollisionResultd obb_hit;
    ASSERT_EQ(meshes_intersect(*obb_a, X_WA, *obb_b, X_WB),
              fcl::collide(obb_a.get(), X_WA, obb_b.get(), X_WB, hit_request, obb_hit) > 0)
        << "pose " << i;
    ASSERT_EQ(meshes_intersect(*obb_a, X_WA, *obb_b, X_WB), collide) << "pose " << i;
    const double cap = rng.uniform(0.01, 0.6);
    for (const double e : {0.0, 0.25}) {
      const double bound = mesh_distance_bound(*obb_a, X_WA, *obb_b, X_WB, cap, e);
      ASSERT_LE(bound, std::min(cap, exact) + 1e-12) << "pose " << i << " e " << e;
      ASSERT_GE(bound, std::min(cap, exact / (1.0 + e)) - 1e-12) << "pose " << i << " e " << e;
      if (e == 0.0 && exact < cap) {
        EXPECT_NEAR(bound, exact, 1e-12);
      }
    }
    intersecting += collide ? 1 : 0;
    near += !collide && exact < cap ? 1 : 0;
    beyond_cap += exact >= cap ? 1 : 0;
  }
  // Every kind of case was met: intersecting, nearer than the cap, farther.
  EXPECT_GT(intersecting, 20);
  EXPECT_GT(near, 20);
  EXPECT_GT(beyond_cap, 20);
}

TEST(MeshProximity, IsTheCapExactlyWhenNothingIsNearer) {
  Rng rng(8);
  const Soup s = random_soup(rng, 50);
  const auto m = model<fcl::OBBd>(s);
  const Eigen::Isometry3d far = Eigen::Translation3d(5.0, 0.0, 0.0) * Eigen::Isometry3d::Identity();
  for (const double cap : {1e-6, 0.1, 0.3, 1.0, 3.0})
    EXPECT_EQ(mesh_distance_bound(*m, Eigen::Isometry3d::Identity(), *m, far, cap, 0.25), cap);
  EXPECT_FALSE(meshes_intersect(*m, Eigen::Isometry3d::Identity(), *m, far));
  // The same soup on itself intersects.
  EXPECT_EQ(mesh_distance_bound(*m, far, *m, far, 1.0, 0.25), 0.0);
  EXPECT_TRUE(meshes_intersect(*m, far, *m, far));
}

TEST(MeshProximity, CountsTheBoxesAndTrianglesItTests) {
  Rng rng(9);
  const Soup s = random_soup(rng, 50);
  const auto m = model<fcl::OBBd>(s);
  const Eigen::Isometry3d here = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d far = Eigen::Translation3d(5.0, 0.0, 0.0) * here;
  // Far apart: the two roots, and nothing below them.
  WalkTests apart;
  EXPECT_FALSE(meshes_intersect(*m, here, *m, far, &apart));
  EXPECT_EQ(apart.boxes, 1u);
  EXPECT_EQ(apart.triangles, 0u);
  EXPECT_EQ(mesh_distance_bound(*m, here, *m, far, 0.1, 0.25, &apart), 0.1);
  EXPECT_EQ(apart.boxes, 2u);  // added to what was there
  // On itself: boxes opened down to a pair of triangles that meet.
  WalkTests met;
  EXPECT_TRUE(meshes_intersect(*m, far, *m, far, &met));
  EXPECT_GT(met.boxes, 2u);
  EXPECT_GE(met.triangles, 1u);
  // A query that searches further tests more, and the same query counts the same again.
  const Eigen::Isometry3d near = Eigen::Translation3d(1.2, 0.0, 0.0) * here;
  WalkTests capped, wider, again;
  const double d1 = mesh_distance_bound(*m, here, *m, near, 0.05, 0.0, &capped);
  const double d2 = mesh_distance_bound(*m, here, *m, near, 1.0, 0.0, &wider);
  mesh_distance_bound(*m, here, *m, near, 1.0, 0.0, &again);
  EXPECT_LE(d1, d2);
  EXPECT_GT(wider.triangles, 0u);
  EXPECT_GT(wider.boxes, capped.boxes);
  EXPECT_EQ(again.boxes, wider.boxes);
  EXPECT_EQ(again.triangles, wider.triangles);
}

}  // namespace
}  // namespace tandem

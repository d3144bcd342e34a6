// tandem's separating-axis test of two boxes held against FCL's own, fcl::obbDisjoint, on random
// pairs and on pairs at the edge of touching, where a face axis parts some and the product of two
// axes others.

#include "tandem/collision/box_separation.hpp"

#include <fcl/math/bv/OBB.h>
#include <gtest/gtest.h>

#include <cmath>

#include "tandem/core/rng.hpp"

namespace tandem {
namespace {

Eigen::Matrix3d random_axes(Rng& rng) {
  return Eigen::Quaterniond(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0),
                            rng.uniform(-1.0, 1.0))
      .normalized()
      .toRotationMatrix();
}

Eigen::Vector3d random_extents(Rng& rng) {
  // Flat and long boxes too: a triangle's box is flat.
  return Eigen::Vector3d(rng.uniform(0.0, 1.0), rng.uniform(0.01, 1.0), rng.uniform(0.0, 0.5));
}

struct Pair {
  Eigen::Matrix3d A, P;
  Eigen::Vector3d a, b, u;  ///< u: the direction from A's centre to P's
};

Pair random_pair(Rng& rng) {
  return {random_axes(rng), random_axes(rng), random_extents(rng), random_extents(rng),
          Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian()).normalized()};
}

/// FCL's answer, B = Aᵀ·P and T = Aᵀ·D computed entry by entry as the walk computes them.
bool fcl_apart(const Pair& p, double s) {
  const Eigen::Vector3d D = s * p.u;
  Eigen::Matrix3d B;
  Eigen::Vector3d T;
  for (int i = 0; i < 3; ++i) {
    T[i] = p.A.col(i).dot(D);
    for (int c = 0; c < 3; ++c)
      B(i, c) = p.A.col(i).dot(p.P.col(c));
  }
  return fcl::obbDisjoint(B, T, p.a, p.b);
}

/// Whether one of the six face axes alone separates the pair (FCL's first six tests).
bool faces_apart(const Pair& p, double s) {
  const Eigen::Matrix3d B = p.A.transpose() * p.P;
  const Eigen::Vector3d T = p.A.transpose() * (s * p.u);
  const Eigen::Matrix3d Bf = B.cwiseAbs().array() + 1e-6;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(T[i]) > p.a[i] + Bf.row(i).dot(p.b) ||
        std::abs(B.col(i).dot(T)) > p.b[i] + Bf.col(i).dot(p.a))
      return true;
  }
  return false;
}

bool tandem_apart(const Pair& p, double s) {
  return boxes_apart(p.A, s * p.u, p.a, p.P, p.b);
}

TEST(BoxSeparation, AnswersAsFclOnRandomPairs) {
  Rng rng(3);
  int apart = 0, overlapping = 0;
  for (int k = 0; k < 200000; ++k) {
    const Pair p = random_pair(rng);
    const double s = rng.uniform(0.0, 3.0);
    const bool fcl_answer = fcl_apart(p, s);
    ASSERT_EQ(tandem_apart(p, s), fcl_answer) << "pair " << k;
    (fcl_answer ? apart : overlapping) += 1;
  }
  EXPECT_GT(apart, 20000);
  EXPECT_GT(overlapping, 20000);
}

TEST(BoxSeparation, AnswersAsFclWhereThePairJustTouches) {
  // Along each direction, the distance of the centres where FCL's answer turns (by bisection to
  // the last bit), and the answers just either side of it. Where no face axis separates the pair
  // just beyond the turn, one of the nine products of axes decided it.
  Rng rng(4);
  int by_faces = 0, by_products = 0;
  for (int k = 0; k < 20000; ++k) {
    const Pair p = random_pair(rng);
    double lo = 0.0, hi = 4.0;  // overlapping at 0, apart at 4 (extents are at most 1)
    ASSERT_FALSE(fcl_apart(p, lo));
    ASSERT_TRUE(fcl_apart(p, hi));
    while (std::nextafter(lo, hi) < hi) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi)
        break;
      (fcl_apart(p, mid) ? hi : lo) = mid;
    }
    ASSERT_EQ(tandem_apart(p, lo), false) << "pair " << k;
    ASSERT_EQ(tandem_apart(p, hi), true) << "pair " << k;
    for (const double s : {std::nextafter(lo, 0.0), std::nextafter(hi, 5.0), 0.5 * (lo + hi)})
      ASSERT_EQ(tandem_apart(p, s), fcl_apart(p, s)) << "pair " << k;
    (faces_apart(p, hi) ? by_faces : by_products) += 1;
  }
  EXPECT_GT(by_faces, 2000);
  EXPECT_GT(by_products, 2000);
}

}  // namespace
}  // namespace tandem

#pragma once
// Clearance along a path: how close the part comes to the obstacles, over the whole motion.
//
// At each state, FCL's distance to the nearest obstacle (CollisionChecker::nearest_obstacle).
// Along each motion a -> b, a certified lower bound on the smallest distance: between fractions s
// and s' no point of the part moves more than L |s - s'| (L = |dt| + angle x radius, the bound
// the exact motion validation uses), so with distances d0 and d1 at the ends of a stretch of
// length h the distance inside it is at least (d0 + d1 - L h) / 2. The motion is bisected where
// that bound is lowest until it is within a share `accuracy` of the smallest distance found (or
// within `floor` of it), so the reported minimum never exceeds the true one and falls short of it
// by at most that (or, when a motion needs more than kMaxClearanceQueries distance queries, by the
// gap between `lower` and `found` it reports).
//
// Threading: drives one CollisionChecker; not thread-safe.

#include <string>
#include <vector>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/planning/path.hpp"

namespace tandem {

struct StateClearance {
  double distance = 0.0;  ///< FCL's distance to the nearest obstacle (0 in collision)
  std::size_t obstacle = 0;
  Eigen::Vector3d point_on_object = Eigen::Vector3d::Zero();  ///< world frame
  Eigen::Vector3d point_on_obstacle = Eigen::Vector3d::Zero();
};

struct SegmentClearance {
  double lower = 0.0;        ///< certified: the distance along the motion is never below it
  double found = 0.0;        ///< the smallest distance measured along it (>= the true minimum)
  double at = 0.0;           ///< the fraction of the motion where `found` was measured
  std::size_t obstacle = 0;  ///< the obstacle nearest there
  std::size_t queries = 0;   ///< distance queries spent on this motion
};

struct PathClearance {
  std::vector<StateClearance> states;
  std::vector<SegmentClearance> segments;  ///< segments[i]: the motion from state i to i + 1
  double accuracy = 0.0;                   ///< relative
  double floor = 0.0;                      ///< absolute, scene units
  /// The smallest certified bound over the motions (the state's distance for a one-state path).
  double lower() const;
};

/// Up to this many distance queries per motion.
inline constexpr std::size_t kMaxClearanceQueries = 4096;

/// `accuracy` in (0, 1): the share of the smallest distance found by which the certified minimum
/// may fall short of it; `floor` > 0: an absolute gap that is always close enough (scene units).
PathClearance path_clearance(const Path& path, CollisionChecker& checker, const SE3Space& space,
                             double accuracy, double floor);

}  // namespace tandem

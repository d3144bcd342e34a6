#include "tandem/scene/goal_region.hpp"

#include <Eigen/Geometry>
#include <limits>

namespace tandem {

bool GoalRegion::contains(const Config& q) const {
  const auto [lo, hi] = posed_box(q);
  // Outside when the two boxes are apart along some axis.
  return (hi.array() < min.array()).any() || (lo.array() > max.array()).any();
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> GoalRegion::posed_box(const Config& q) const {
  const Eigen::Isometry3d X = q.pose();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& p : points) {
    const Eigen::Vector3d w = X * p;
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
  }
  return {lo, hi};
}

}  // namespace tandem

#pragma once
// Axis-aligned workspace bounds on the object's reference point, in world coordinates.

#include <Eigen/Core>

namespace tandem {

struct Bounds {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();
  Eigen::Vector3d max = Eigen::Vector3d::Zero();

  bool contains(const Eigen::Vector3d& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
  /// Grows the box to contain p (OMPL.app grows its bounds to contain start and goal).
  void include(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  Eigen::Vector3d extent() const { return max - min; }
  bool is_valid() const {
    return (min.array() <= max.array()).all() && min.allFinite() && max.allFinite();
  }
};

}  // namespace tandem

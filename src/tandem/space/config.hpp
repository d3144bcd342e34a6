#pragma once
// A configuration of the moving object: its pose in the world frame (X_WO), a value type.
//
// Translation t is the position of the object's reference point (for OMPL.app problems the mean of
// the robot mesh vertices; for tandem scenarios the object frame's origin). Rotation q is a unit
// quaternion; q and -q are the same rotation, and every function of tandem treats them alike.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tandem {

struct Config {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();

  Eigen::Isometry3d pose() const {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = q.toRotationMatrix();
    X.translation() = t;
    return X;
  }

  /// Bitwise equality of the stored numbers (q and -q compare different here; use the space's
  /// distance for geometric equality).
  friend bool operator==(const Config& a, const Config& b) {
    return a.t == b.t && a.q.coeffs() == b.q.coeffs();
  }
};

}  // namespace tandem

#include "tandem/interaction/contact_frame.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace tandem {

Eigen::Matrix3d gram_schmidt(const Eigen::Vector3d& n) {
  int axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
  const Eigen::Vector3d i = (e - e.dot(n) * n).normalized();
  const Eigen::Vector3d j = n.cross(i);
  Eigen::Matrix3d R;
  R << i, j, n;
  return R;
}

std::optional<ContactFrame> find_local_frame(const NearestObstacle& nearest,
                                             const Config& q_device) {
  if (nearest.in_collision || !std::isfinite(nearest.distance))
    return std::nullopt;
  const Eigen::Vector3d d = nearest.point_on_object - nearest.point_on_obstacle;
  const double length = d.norm();
  // Below this the points' difference is rounding noise, not a direction.
  if (!(length > 1e-12))
    return std::nullopt;
  ContactFrame f;
  f.P_o = nearest.point_on_obstacle;
  f.P_n = nearest.point_on_object;
  f.P_c = q_device.t;
  f.n = d / length;
  f.R = gram_schmidt(f.n);
  f.delta = f.n.dot(f.P_n - f.P_c);
  f.distance = length;
  f.obstacle = nearest.obstacle;
  return f;
}

}  // namespace tandem

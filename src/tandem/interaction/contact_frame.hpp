#pragma once
// Find_Local_Frame of Blin et al., "I-RRT-C: Interactive Motion Planning with Contact" (IROS 2016),
// Algorithm 2, line 1: the local frame at the nearest obstacle, computed by the operator thread.
//
//   n     = (P_n - P_o) / |P_n - P_o|   the obstacle's normal, from the obstacle to the object
//   delta = n^T (P_n - P_c)             how far the object's nearest point lies from its centre
//                                       along n
//   R     = GramSchmidt(n) = [i j n]    rotation from the local frame (the tangent plane is
//                                       z = 0) to the world frame
//
// P_o is the nearest point on the obstacle, P_n the nearest point on the object, P_c = q_device's
// translation (the object's reference point). All in the world frame.

#include <Eigen/Core>
#include <cstddef>
#include <optional>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/space/config.hpp"

namespace tandem {

struct ContactFrame {
  Eigen::Vector3d P_o = Eigen::Vector3d::Zero();
  Eigen::Vector3d P_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d P_c = Eigen::Vector3d::Zero();
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  double delta = 0.0;
  double distance = 0.0;  ///< |P_n - P_o|, the object's distance to the obstacle
  std::size_t obstacle = 0;
};

/// An orthonormal frame whose third axis is n (unit): Gram-Schmidt from the world axis least
/// aligned with n, so the result is well conditioned and a continuous function of n away from ties.
Eigen::Matrix3d gram_schmidt(const Eigen::Vector3d& n);

/// The frame at the nearest obstacle; nothing when the object touches or penetrates it (FCL's
/// distance is not signed, so the normal is then unknown) or when there is no obstacle.
std::optional<ContactFrame> find_local_frame(const NearestObstacle& nearest,
                                             const Config& q_device);

}  // namespace tandem

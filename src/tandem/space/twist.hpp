#pragma once
// A velocity (or small displacement) in SE(3): linear part first, angular part (world frame) last.

#include <Eigen/Core>

namespace tandem {

/// Linear (first three) and angular (last three, world frame) velocity, per unit of time.
using Twist = Eigen::Matrix<double, 6, 1>;

}  // namespace tandem

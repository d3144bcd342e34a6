#pragma once
// Rotations read from files: four numbers (or an axis) made unit length without overflowing. A file
// may give any finite numbers, but squaring 1e200 overflows: the norm is infinite, and dividing by it
// would leave a zero quaternion (or axis) where the user wrote a valid direction. Such numbers are
// scaled by their largest magnitude first; others are normalised as Eigen's normalized() does, bit
// for bit.

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

namespace tandem {

/// Four numbers whose norm is at most this are refused as a rotation by every reader (files,
/// traces, the viewer's messages, the Python module): they are zero, or too near it for their
/// direction to mean anything.
inline constexpr double kMinQuaternionNorm = 1e-9;
/// The readers of what tandem writes (traces, paths) keep four numbers whose norm is within this
/// of 1 bit for bit: a unit quaternion written out and read back stays the same.
inline constexpr double kUnitQuaternionSlack = 1e-12;

/// `v` divided by its norm, or nullopt when a component is not finite or the norm is at most
/// `min_norm`. When the norm is within `keep_within` of 1, `v` itself.
template <typename Vector>
std::optional<Vector> unit_direction(const Vector& v, double min_norm = 0.0,
                                     double keep_within = 0.0) {
  if (!v.allFinite())
    return std::nullopt;
  const double norm = v.norm();
  if (std::isfinite(norm)) {
    if (!(norm > min_norm))
      return std::nullopt;
    return std::abs(norm - 1.0) <= keep_within ? v : Vector(v / norm);
  }
  const Vector scaled = v / v.cwiseAbs().maxCoeff();  // the norm overflowed: it is huge
  return Vector(scaled / scaled.norm());
}

/// The unit quaternion of w + xi + yj + zk (see unit_direction).
inline std::optional<Eigen::Quaterniond> unit_quaternion(double w, double x, double y, double z,
                                                         double min_norm = kMinQuaternionNorm,
                                                         double keep_within = 0.0) {
  const std::optional<Eigen::Vector4d> unit =
      unit_direction(Eigen::Vector4d(x, y, z, w), min_norm, keep_within);  // Eigen's order
  if (!unit)
    return std::nullopt;
  return Eigen::Quaterniond(*unit);
}

}  // namespace tandem

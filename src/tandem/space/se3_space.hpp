#pragma once
// The configuration space of a rigid object: SE(3) (free flyer), or its planar subspace (x, y,
// yaw).
//
// Metric. d(a, b) = w_t * |t_a - t_b| + w_r * angle(q_a, q_b), where angle is the rotation angle in
// radians in [0, pi] between the two orientations (so q and -q are at distance 0). The default
// weights (w_t = 1, w_r = 0.5) make d equal to OMPL's SE3StateSpace distance (|dt| +
// acos|<q_a,q_b>|) and to OMPL's SE2StateSpace distance (|dxy| + 0.5 |dtheta|), so ranges and
// benchmark settings compare.
//
// Motion resolution, as OMPL's longestValidSegmentFraction f (default 0.01): a motion is checked at
// n = max(ceil(|dt| / (f * diagonal)), ceil(angle / (f * pi))) segments, i.e. steps of 1% of the
// bounds diagonal in translation and 1% of pi/2 in OMPL's half-angle rotation distance.
//
// Planar mode: z is fixed at bounds.min.z and rotations are about the world z axis only; the same
// formulas then reduce to OMPL's SE(2).
//
// Value type, immutable after construction; safe to share between threads.

#include <cstdint>

#include "tandem/core/rng.hpp"
#include "tandem/space/bounds.hpp"
#include "tandem/space/config.hpp"

namespace tandem {

enum class SpaceKind { se3, planar };

struct MetricWeights {
  double translation = 1.0;  ///< per unit of length of translation
  double rotation = 0.5;     ///< per radian of rotation angle
};

class SE3Space {
 public:
  static constexpr double kDefaultResolution = 0.01;

  /// Throws InputError (source "bounds" / "resolution" / "weights") for invalid arguments.
  SE3Space(SpaceKind kind, const Bounds& bounds, MetricWeights weights = {},
           double resolution = kDefaultResolution);

  SpaceKind kind() const { return kind_; }
  bool planar() const { return kind_ == SpaceKind::planar; }
  const Bounds& bounds() const { return bounds_; }
  const MetricWeights& weights() const { return weights_; }
  double resolution() const { return resolution_; }

  /// Rotation angle in radians, in [0, pi], between two unit quaternions; q and -q give 0.
  static double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

  /// For unit quaternions the chord |a - b| (one hemisphere) is 2 sin(theta / 4) <= theta / 2. The
  /// factor stays below 2 by enough to absorb rounding and quaternions normalised to within 1e-6.
  static constexpr double kChordBound = 2.0 * (1.0 - 1e-6);

  /// A lower bound of rotation_angle(a, b) without its atan2, within 10% of it at any angle: twice
  /// the chord |a - b| between the quaternions on one hemisphere (see rotation_angle).
  static double rotation_lower_bound(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    const Eigen::Vector4d va = a.coeffs();
    const Eigen::Vector4d vb = b.coeffs();
    const double chord = va.dot(vb) < 0.0 ? (va + vb).norm() : (va - vb).norm();
    return kChordBound * chord;
  }

  double distance(const Config& a, const Config& b) const {
    return weights_.translation * (a.t - b.t).norm() + weights_.rotation * rotation_angle(a.q, b.q);
  }

  /// Point at fraction s in [0, 1] along the geodesic from a to b (linear in translation, slerp on
  /// the shorter arc in rotation). interpolate(a, b, 0) == a.
  Config interpolate(const Config& a, const Config& b, double s) const;

  /// The k-th of n equal steps from a to b, computed so that step(a, b, k, n) == step(b, a, n - k,
  /// n) bit for bit: a motion checked in either direction visits exactly the same configurations.
  Config step(const Config& a, const Config& b, unsigned k, unsigned n) const;

  /// Number of segments a motion is checked at (0 when a and b coincide).
  unsigned segment_count(const Config& a, const Config& b) const;

  /// Uniform in the bounds, uniform on SO(3) (Shoemake) or on the yaw circle for planar spaces.
  Config sample_uniform(Rng& rng) const;

  bool satisfies_bounds(const Config& q) const { return bounds_.contains(q.t); }
  /// A pose the space can hold: q clamped to the bounds, its quaternion normalised, and for a
  /// planar space put on the plane with its yaw.
  Config admissible(Config q) const;

  /// Length of the bounds' diagonal (over x, y only for a planar space).
  double translation_extent() const { return translation_extent_; }
  /// Largest distance between two configurations: w_t * diagonal + w_r * pi.
  double max_extent() const {
    return weights_.translation * translation_extent_ + weights_.rotation * kPi;
  }
  double translation_step() const { return resolution_ * translation_extent_; }
  double rotation_step() const { return resolution_ * kPi; }
  /// OMPL's default planner range: 0.2 x the maximum extent.
  double default_range() const { return 0.2 * max_extent(); }

  /// A planar configuration (x, y, yaw), z at the plane's height.
  Config planar_config(double x, double y, double yaw) const;
  /// Yaw angle in (-pi, pi] of a rotation about z.
  static double yaw(const Eigen::Quaterniond& q);

 private:
  static constexpr double kPi = 3.14159265358979323846;

  SpaceKind kind_;
  Bounds bounds_;
  MetricWeights weights_;
  double resolution_;
  double translation_extent_;
};

/// Slerp on the shorter arc between unit quaternions; the result is normalised.
Eigen::Quaterniond slerp_shortest(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                                  double s);

/// A strict weak order on configurations (lexicographic on the stored numbers).
bool lexicographic_less(const Config& a, const Config& b);

}  // namespace tandem

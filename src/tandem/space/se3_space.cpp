#include "tandem/space/se3_space.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tandem/core/error.hpp"

namespace tandem {

SE3Space::SE3Space(SpaceKind kind, const Bounds& bounds, MetricWeights weights, double resolution)
    : kind_(kind), bounds_(bounds), weights_(weights), resolution_(resolution) {
  if (!bounds_.is_valid()) {
    std::ostringstream os;
    os << "invalid workspace bounds: min (" << bounds_.min.transpose() << ") must not exceed max ("
       << bounds_.max.transpose() << ") and both must be finite";
    throw InputError("bounds", os.str());
  }
  if (!(resolution_ > 0.0 && resolution_ < 1.0)) {
    throw InputError("resolution", "must be in (0, 1), got " + std::to_string(resolution_));
  }
  if (!(weights_.translation > 0.0) || !(weights_.rotation >= 0.0) ||
      !std::isfinite(weights_.translation) || !std::isfinite(weights_.rotation)) {
    throw InputError("weights", "translation weight must be > 0 and rotation weight >= 0");
  }
  if (planar()) {
    bounds_.max.z() = bounds_.min.z();
    translation_extent_ = bounds_.extent().head<2>().norm();
  } else {
    translation_extent_ = bounds_.extent().norm();
  }
  if (!(translation_extent_ > 0.0)) {
    throw InputError("bounds", "the workspace bounds have zero extent");
  }
}

double SE3Space::rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // With b flipped onto a's hemisphere, the two unit 4-vectors are theta/2 apart for a rotation of
  // theta, and atan2(|a - b|, |a + b|) is half of that. Accurate near 0 and near pi, unlike
  // 2 acos|<a, b>|.
  const Eigen::Vector4d va = a.coeffs();
  Eigen::Vector4d vb = b.coeffs();
  if (va.dot(vb) < 0.0)
    vb = -vb;
  return 4.0 * std::atan2((va - vb).norm(), (va + vb).norm());
}

Eigen::Quaterniond slerp_shortest(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b,
                                  double s) {
  const Eigen::Vector4d va = a.coeffs();
  Eigen::Vector4d vb = b.coeffs();
  double d = va.dot(vb);
  if (d < 0.0) {
    vb = -vb;
    d = -d;
  }
  Eigen::Vector4d v;
  if (d > 1.0 - 1e-12) {
    v = (1.0 - s) * va + s * vb;
  } else {
    const double theta = std::acos(std::min(d, 1.0));
    const double inv = 1.0 / std::sin(theta);
    v = std::sin((1.0 - s) * theta) * inv * va + std::sin(s * theta) * inv * vb;
  }
  v.normalize();
  return Eigen::Quaterniond(v[3], v[0], v[1], v[2]);
}

bool lexicographic_less(const Config& a, const Config& b) {
  for (int i = 0; i < 3; ++i) {
    if (a.t[i] != b.t[i])
      return a.t[i] < b.t[i];
  }
  for (int i = 0; i < 4; ++i) {
    if (a.q.coeffs()[i] != b.q.coeffs()[i])
      return a.q.coeffs()[i] < b.q.coeffs()[i];
  }
  return false;
}

Config SE3Space::admissible(Config q) const {
  q.t = q.t.cwiseMax(bounds_.min).cwiseMin(bounds_.max);
  q.q.normalize();
  if (planar())
    q = planar_config(q.t.x(), q.t.y(), yaw(q.q));
  return q;
}

Config SE3Space::interpolate(const Config& a, const Config& b, double s) const {
  Config r;
  r.t = a.t + s * (b.t - a.t);
  r.q = slerp_shortest(a.q, b.q, s);
  return r;
}

Config SE3Space::step(const Config& a, const Config& b, unsigned k, unsigned n) const {
  if (k == 0)
    return a;
  if (k == n)
    return b;
  // Always interpolate from the lexicographically smaller end, with an exact integer complement.
  if (lexicographic_less(b, a)) {
    return interpolate(b, a, static_cast<double>(n - k) / static_cast<double>(n));
  }
  return interpolate(a, b, static_cast<double>(k) / static_cast<double>(n));
}

unsigned SE3Space::segment_count(const Config& a, const Config& b) const {
  const double nt = std::ceil((a.t - b.t).norm() / translation_step());
  const double nr = std::ceil(rotation_angle(a.q, b.q) / rotation_step());
  return static_cast<unsigned>(std::max(nt, nr));
}

Config SE3Space::sample_uniform(Rng& rng) const {
  Config c;
  if (planar()) {
    c.t = Eigen::Vector3d(rng.uniform(bounds_.min.x(), bounds_.max.x()),
                          rng.uniform(bounds_.min.y(), bounds_.max.y()), bounds_.min.z());
    const double yaw = rng.uniform(-kPi, kPi);
    c.q = Eigen::Quaterniond(std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw));
    return c;
  }
  for (int i = 0; i < 3; ++i)
    c.t[i] = rng.uniform(bounds_.min[i], bounds_.max[i]);
  // Shoemake, "Uniform random rotations", Graphics Gems III (1992).
  const double u1 = rng.uniform01();
  const double u2 = 2.0 * kPi * rng.uniform01();
  const double u3 = 2.0 * kPi * rng.uniform01();
  const double a = std::sqrt(1.0 - u1);
  const double b = std::sqrt(u1);
  c.q = Eigen::Quaterniond(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
  return c;
}

Config SE3Space::planar_config(double x, double y, double yaw_angle) const {
  Config c;
  c.t = Eigen::Vector3d(x, y, bounds_.min.z());
  c.q = Eigen::Quaterniond(std::cos(0.5 * yaw_angle), 0.0, 0.0, std::sin(0.5 * yaw_angle));
  return c;
}

double SE3Space::yaw(const Eigen::Quaterniond& q) {
  // For a rotation about z only, q = (cos(y/2), 0, 0, sin(y/2)); the general formula is the z-y-x
  // yaw.
  const double siny = 2.0 * (q.w() * q.z() + q.x() * q.y());
  const double cosy = 1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z());
  return std::atan2(siny, cosy);
}

}  // namespace tandem

#include "tandem/sampling/gaussian_shooter.hpp"

#include <cmath>

namespace tandem {

Twist tangent_difference(const Config& a, const Config& b) {
  Twist d;
  d.head<3>() = b.t - a.t;
  Eigen::Quaterniond dq = b.q * a.q.inverse();
  if (dq.w() < 0.0)
    dq.coeffs() = -dq.coeffs();
  const Eigen::AngleAxisd aa(dq.normalized());
  d.tail<3>() = aa.angle() * aa.axis();
  return d;
}

Config gaussian_shot(const SE3Space& space, const Config& centre, const Twist& force,
                     double sigma_t, double sigma_r, Rng& rng) {
  const bool planar = space.planar();
  // Work in units of the deviations, so that translation and rotation compare.
  Twist z;
  for (int i = 0; i < 6; ++i)
    z[i] = rng.gaussian();
  Twist f;
  f.head<3>() = force.head<3>() / sigma_t;
  f.tail<3>() = force.tail<3>() / sigma_r;
  if (planar) {
    z[2] = z[3] = z[4] = 0.0;
    f[2] = f[3] = f[4] = 0.0;
  }
  const double strength = f.norm();
  if (strength > 1e-12) {
    const Twist u = f / strength;
    z += strength * u.dot(z) * u;  // (k - 1) = strength
  }
  Config q = centre;
  q.t += sigma_t * z.head<3>();
  const Eigen::Vector3d rv = sigma_r * z.tail<3>();
  if (rv.norm() > 0.0)
    q.q = (Eigen::Quaterniond(Eigen::AngleAxisd(rv.norm(), rv.normalized())) * q.q).normalized();
  q.t = q.t.cwiseMax(space.bounds().min).cwiseMin(space.bounds().max);
  return q;
}

}  // namespace tandem

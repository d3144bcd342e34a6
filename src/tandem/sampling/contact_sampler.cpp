#include "tandem/sampling/contact_sampler.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace tandem {
namespace {

/// The polygon where the plane {x : n.(x - p) = 0} cuts the box, as its vertices in order.
std::vector<Eigen::Vector3d> plane_box_polygon(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                               const Bounds& box) {
  std::vector<Eigen::Vector3d> points;
  const Eigen::Vector3d lo = box.min, hi = box.max;
  // The 12 edges of the box: from each corner with coordinate axis a at lo, along a.
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector3d start;
      start[a] = lo[a];
      start[b] = (k & 1) ? hi[b] : lo[b];
      start[c] = (k & 2) ? hi[c] : lo[c];
      const double f0 = n.dot(start - p);
      const double slope = n[a] * (hi[a] - lo[a]);
      if (slope == 0.0)
        continue;
      const double s = -f0 / slope;
      if (s < 0.0 || s > 1.0)
        continue;
      Eigen::Vector3d q = start;
      q[a] = lo[a] + s * (hi[a] - lo[a]);
      points.push_back(q);
    }
  }
  if (points.size() < 3)
    return points;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& q : points)
    centre += q / static_cast<double>(points.size());
  const Eigen::Matrix3d R = gram_schmidt(n);
  std::sort(points.begin(), points.end(), [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    const Eigen::Vector3d lx = R.transpose() * (x - centre), ly = R.transpose() * (y - centre);
    return std::atan2(lx.y(), lx.x()) < std::atan2(ly.y(), ly.x());
  });
  return points;
}

/// Uniform in a convex polygon (a fan of triangles from its first vertex, picked by area).
Eigen::Vector3d uniform_in_polygon(const std::vector<Eigen::Vector3d>& poly, Rng& rng) {
  std::vector<double> areas;
  double total = 0.0;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
    total += 0.5 * (poly[k] - poly[0]).cross(poly[k + 1] - poly[0]).norm();
    areas.push_back(total);
  }
  const double pick = rng.uniform01() * total;
  std::size_t k = 0;
  while (k + 1 < areas.size() && areas[k] < pick)
    ++k;
  double u = rng.uniform01(), v = rng.uniform01();
  if (u + v > 1.0) {
    u = 1.0 - u;
    v = 1.0 - v;
  }
  return poly[0] + u * (poly[k + 1] - poly[0]) + v * (poly[k + 2] - poly[0]);
}

/// The range [lo, hi] of s for which c + s dir lies in the bounds along the first `axes` axes;
/// nothing if the line misses them.
std::optional<std::pair<double, double>> clip_line(const Eigen::Vector3d& c,
                                                   const Eigen::Vector3d& dir, const Bounds& b,
                                                   int axes) {
  double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
  for (int a = 0; a < axes; ++a) {
    if (std::abs(dir[a]) < 1e-12) {
      if (c[a] < b.min[a] || c[a] > b.max[a])
        return std::nullopt;
      continue;
    }
    double s0 = (b.min[a] - c[a]) / dir[a], s1 = (b.max[a] - c[a]) / dir[a];
    if (s0 > s1)
      std::swap(s0, s1);
    lo = std::max(lo, s0);
    hi = std::min(hi, s1);
  }
  if (!(lo <= hi))
    return std::nullopt;
  return std::pair{lo, hi};
}

/// The translation that puts the object `clearance` above each frame's plane, from the reference
/// point t0 (moving along the normals only): the point for three frames, the line's point
/// nearest t0 and its direction for two.
struct Constrained {
  Eigen::Vector3d point;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< zero for a point
};

std::optional<Constrained> above_planes(const std::vector<ContactFrame>& frames,
                                        const Eigen::Vector3d& t0, double clearance) {
  const auto rise = [&](const ContactFrame& f) { return -(f.distance - clearance); };
  if (frames.size() == 2) {
    const Eigen::Vector3d &n1 = frames[0].n, &n2 = frames[1].n;
    const double g = n1.dot(n2), det = 1.0 - g * g;
    if (!(det > 1e-9))
      return std::nullopt;
    const double r1 = rise(frames[0]), r2 = rise(frames[1]);
    const double a = (r1 - g * r2) / det, b = (r2 - g * r1) / det;
    return Constrained{t0 + a * n1 + b * n2, n1.cross(n2).normalized()};
  }
  Eigen::Matrix3d N;
  Eigen::Vector3d r;
  for (int k = 0; k < 3; ++k) {
    N.row(k) = frames[static_cast<std::size_t>(k)].n.transpose();
    r[k] = rise(frames[static_cast<std::size_t>(k)]);
  }
  if (!(std::abs(N.determinant()) > 1e-6))
    return std::nullopt;
  return Constrained{t0 + N.fullPivLu().solve(r)};
}

}  // namespace

std::vector<ContactFrame> distinct_surfaces(const std::vector<ContactFrame>& frames,
                                            std::size_t most) {
  const double cos30 = std::sqrt(3.0) / 2.0;
  std::vector<ContactFrame> kept;
  for (const ContactFrame& f : frames) {
    if (kept.size() >= most)
      break;
    const bool apart = std::all_of(kept.begin(), kept.end(), [&](const ContactFrame& k) {
      return std::abs(k.n.dot(f.n)) < cos30;
    });
    if (apart)
      kept.push_back(f);
  }
  return kept;
}

std::optional<Config> sample_contact_surfaces(const std::vector<ContactFrame>& frames,
                                              const Eigen::Quaterniond& q_operator,
                                              const SE3Space& space, double clearance, double turn,
                                              Rng& rng) {
  if (frames.empty() || frames.size() > 3)
    return std::nullopt;
  const ContactFrame& first = frames.front();
  // The turn about the first normal, about the object's nearest point P_n. Without one, the
  // operator's orientation as it is: one frame is then the papers' sampler, bit for bit.
  const double angle = turn > 0.0 ? rng.uniform(-turn, turn) : 0.0;
  const Eigen::AngleAxisd R(angle, first.n);
  const Eigen::Quaterniond q =
      angle != 0.0 ? (Eigen::Quaterniond(R) * q_operator).normalized() : q_operator;
  if (frames.size() == 1 || space.planar())
    return sample_contact(first, q, space, clearance, rng);
  const Eigen::Vector3d t0 = first.P_n + R * (first.P_c - first.P_n);
  const std::optional<Constrained> c = above_planes(frames, t0, clearance);
  if (!c)
    return std::nullopt;
  Config out;
  out.q = q;
  if (frames.size() == 3) {
    out.t = c->point;
    return space.satisfies_bounds(out) ? std::optional<Config>(out) : std::nullopt;
  }
  const Bounds& b = space.bounds();
  const auto range = clip_line(c->point, c->direction, b, 3);
  if (!range)
    return std::nullopt;
  // Rounding may leave the end a hair outside.
  out.t = (c->point + rng.uniform(range->first, range->second) * c->direction)
              .cwiseMax(b.min)
              .cwiseMin(b.max);
  return out;
}

std::optional<Config> sample_contact(const ContactFrame& frame,
                                     const Eigen::Quaterniond& q_operator, const SE3Space& space,
                                     double clearance, Rng& rng) {
  // Move onto contact: the object's nearest point goes from P_n to `clearance` above the tangent
  // plane.
  const Eigen::Vector3d to_contact = -(frame.distance - clearance) * frame.n;
  const Bounds& b = space.bounds();
  Config q;
  q.q = q_operator;
  if (space.planar()) {
    // The line through P_c perpendicular to n (in the plane of motion), clipped to the bounds.
    Eigen::Vector2d n2 = frame.n.head<2>();
    if (!(n2.norm() > 1e-9))
      return std::nullopt;
    n2.normalize();
    const Eigen::Vector2d dir(-n2.y(), n2.x());
    const Eigen::Vector2d c = frame.P_c.head<2>() + to_contact.head<2>();
    const auto range = clip_line({c.x(), c.y(), 0.0}, {dir.x(), dir.y(), 0.0}, b, 2);
    if (!range)
      return std::nullopt;
    const Eigen::Vector2d p = c + rng.uniform(range->first, range->second) * dir;
    q.t = Eigen::Vector3d(p.x(), p.y(), b.min.z());
    return q;
  }
  const Eigen::Vector3d centre = frame.P_c + to_contact;
  const std::vector<Eigen::Vector3d> poly = plane_box_polygon(centre, frame.n, b);
  if (poly.size() < 3)
    return std::nullopt;
  q.t = uniform_in_polygon(poly, rng);
  // Rounding may leave a vertex a hair outside.
  q.t = q.t.cwiseMax(b.min).cwiseMin(b.max);
  return q;
}

}  // namespace tandem

#include "tandem/planning/path_clearance.hpp"

#include <algorithm>
#include <queue>
#include <stdexcept>

namespace tandem {
namespace {

/// A stretch [s0, s1] of a motion with the distances at its ends and its certified bound.
struct Stretch {
  double s0, s1, d0, d1, lower;
  bool operator<(const Stretch& o) const { return lower > o.lower; }  // lowest first
};

Stretch stretch(double s0, double s1, double d0, double d1, double rate) {
  const double inside = 0.5 * (d0 + d1 - rate * (s1 - s0));
  return {s0, s1, d0, d1, std::min({inside, d0, d1})};
}

StateClearance measure(CollisionChecker& checker, const Config& q) {
  const NearestObstacle n = checker.nearest_obstacle(q);
  return {n.in_collision ? 0.0 : n.distance, n.obstacle, n.point_on_object, n.point_on_obstacle};
}

SegmentClearance motion_clearance(const Config& a, const Config& b, const StateClearance& ca,
                                  const StateClearance& cb, CollisionChecker& checker,
                                  const SE3Space& space, double accuracy, double floor) {
  // No point of the part moves more than rate |s - s'| (a hair more, for rounding).
  const double rate =
      ((a.t - b.t).norm() + SE3Space::rotation_angle(a.q, b.q) * checker.object_radius()) *
      (1.0 + 1e-9);
  SegmentClearance seg;
  const bool a_nearer = ca.distance <= cb.distance;
  seg.found = a_nearer ? ca.distance : cb.distance;
  seg.at = a_nearer ? 0.0 : 1.0;
  seg.obstacle = a_nearer ? ca.obstacle : cb.obstacle;
  std::priority_queue<Stretch> open;
  open.push(stretch(0.0, 1.0, ca.distance, cb.distance, rate));
  auto close_enough = [&] {
    return open.top().lower >= seg.found - std::max(accuracy * seg.found, floor);
  };
  while (!close_enough() && seg.queries < kMaxClearanceQueries) {
    const Stretch s = open.top();
    open.pop();
    const double mid = 0.5 * (s.s0 + s.s1);
    const StateClearance c = measure(checker, space.interpolate(a, b, mid));
    ++seg.queries;
    if (c.distance < seg.found) {
      seg.found = c.distance;
      seg.at = mid;
      seg.obstacle = c.obstacle;
    }
    open.push(stretch(s.s0, mid, s.d0, c.distance, rate));
    open.push(stretch(mid, s.s1, c.distance, s.d1, rate));
  }
  seg.lower = std::max(0.0, open.top().lower);
  return seg;
}

}  // namespace

double PathClearance::lower() const {
  double m = states.empty() ? 0.0 : states.front().distance;
  for (const auto& s : states)
    m = std::min(m, s.distance);
  for (const auto& s : segments)
    m = std::min(m, s.lower);
  return m;
}

PathClearance path_clearance(const Path& path, CollisionChecker& checker, const SE3Space& space,
                             double accuracy, double floor) {
  if (!(accuracy > 0.0 && accuracy < 1.0) || !(floor > 0.0))
    throw std::invalid_argument("path_clearance: accuracy in (0, 1) and a positive floor");
  PathClearance out;
  out.accuracy = accuracy;
  out.floor = floor;
  for (const Config& q : path)
    out.states.push_back(measure(checker, q));
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    out.segments.push_back(motion_clearance(path[i], path[i + 1], out.states[i], out.states[i + 1],
                                            checker, space, accuracy, floor));
  }
  return out;
}

}  // namespace tandem

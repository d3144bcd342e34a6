#include "tandem/sampling/guided_sampler.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tandem {

GuidedSampler::GuidedSampler(const SE3Space& space, const CollisionChecker& checker,
                             const Config& start, const Config& goal, double share,
                             std::shared_ptr<const WorkspaceRoute> route)
    : space_(space),
      checker_(checker),
      start_(start.t),
      goal_(goal.t),
      share_(share),
      route_(std::move(route)) {}

WorkspaceRoute workspace_route(const SE3Space& space, const CollisionChecker& checker,
                               const Eigen::Vector3d& start, const Eigen::Vector3d& goal) {
  WorkspaceRoute route{.points = {}, .extent = checker.object_extent()};
  const DistanceGrid* grid = checker.distance_grid();
  const GuideBlocks* blocks = checker.guide_blocks();
  if (grid == nullptr || blocks == nullptr || space.planar())
    return route;
  std::vector<GuidePoint>& points = route.points;
  points = find_guide(*grid, *blocks, start, goal, route.extent.half_extents.maxCoeff());
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k)
    length += (points[k].point - points[k - 1].point).norm();
  if (points.size() < 2 || !(length > 0.0))
    points.clear();
  return route;
}

bool fits_lengthwise(const WorkspaceRoute& route) {
  if (route.points.empty())
    return false;
  double narrowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k + 1 < route.points.size(); ++k)
    narrowest = std::min(narrowest, route.points[k].clearance);
  return narrowest >= route.extent.half_extents(1);
}

void GuidedSampler::find() {
  if (route_ == nullptr)
    route_ =
        std::make_shared<const WorkspaceRoute>(workspace_route(space_, checker_, start_, goal_));
  found_ = true;
  const std::vector<GuidePoint>& points = route_->points;
  long_axis_ = route_->extent.axes.col(0);
  least_spread_ = 0.1 * route_->extent.half_extents.maxCoeff();
  double s = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (k > 0)
      s += (points[k].point - points[k - 1].point).norm();
    length_.push_back(s);
  }
  covered_.assign(points.size(), false);
  lengthwise_ = fits_lengthwise(*route_);
  uncovered_ = points.size();
  measure_open();
}

void GuidedSampler::measure_open() {
  open_length_.assign(length_.size(), 0.0);
  for (std::size_t k = 1; k < length_.size(); ++k) {
    const bool open = !covered_[k - 1] || !covered_[k];
    open_length_[k] = open_length_[k - 1] + (open ? length_[k] - length_[k - 1] : 0.0);
  }
}

void GuidedSampler::cover(const Eigen::Vector3d& p) {
  if (!covering())
    return;
  const std::size_t before = uncovered_;
  for (std::size_t k = 0; k < guide().size(); ++k) {
    const GuidePoint& g = guide()[k];
    if (!covered_[k] && (g.point - p).norm() <= std::max(least_spread_, g.clearance)) {
      covered_[k] = true;
      --uncovered_;
    }
  }
  if (lengthwise_ && uncovered_ != before)
    measure_open();
}

void GuidedSampler::sample(const SampleRequest& request, std::vector<Target>& out) {
  Rng& rng = *request.rng;
  if (share_ > 0.0 && !found_)
    find();
  started_ =
      started_ || (!guide().empty() && request.iteration >= (lengthwise_ ? 0 : kGuideWarmup));
  Config q = space_.sample_uniform(rng);
  if (started_ && uncovered_ == 0 && retire_at_ == 0)
    retire_at_ = 2 * request.iteration;
  const bool guiding = started_ && (uncovered_ > 0 || request.iteration < retire_at_);
  if (guiding && rng.uniform01() < share_)
    along(rng, q);
  out.push_back({q, NodeSource::random});
}

void GuidedSampler::along(Rng& rng, Config& q) const {
  const std::vector<GuidePoint>& g = route_->points;
  // By length along the whole guide, or, where the part fits it lengthwise, along its open part.
  const std::vector<double>& by = lengthwise_ && uncovered_ > 0 ? open_length_ : length_;
  const double s = rng.uniform(0.0, by.back());
  const std::size_t k = static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(std::upper_bound(by.begin(), by.end(), s) - by.begin(), 1,
                                 static_cast<std::ptrdiff_t>(g.size()) - 1));
  const double span = by[k] - by[k - 1];
  const double u = span > 0.0 ? (s - by[k - 1]) / span : 0.0;
  const Eigen::Vector3d p = g[k - 1].point + u * (g[k].point - g[k - 1].point);
  const double spread =
      std::max(least_spread_, g[k - 1].clearance + u * (g[k].clearance - g[k - 1].clearance));
  // A sample turned along the route lies near its centreline, where the part fits lengthwise.
  const bool turned = lengthwise_ && span > 0.0 && rng.uniform01() < 0.5;
  const double sigma = turned ? kTurnedSpread * spread : spread;
  const Eigen::Vector3d moved =
      p + sigma * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian());
  const Bounds& b = space_.bounds();
  q.t = moved.cwiseMax(b.min).cwiseMin(b.max);
  if (!turned)
    return;
  const Eigen::Vector3d along_route = g[k].point - g[k - 1].point;
  const Eigen::Vector3d axis = (rng.uniform01() < 0.5 ? 1.0 : -1.0) * along_route.normalized();
  q.q = Eigen::AngleAxisd(rng.uniform(-M_PI, M_PI), axis) *
        Eigen::Quaterniond::FromTwoVectors(long_axis_, axis);
}

}  // namespace tandem

#include "tandem/sampling/guided_sampler.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tandem {

GuidedSampler::GuidedSampler(const SE3Space& space, const CollisionChecker& checker,
                             const Config& start, const Config& goal, double share)
    : space_(space), checker_(checker), start_(start.t), goal_(goal.t), share_(share) {}

std::vector<GuidePoint> workspace_route(const SE3Space& space, const CollisionChecker& checker,
                                        const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                                        const ObjectExtent& extent) {
  const DistanceGrid* grid = checker.distance_grid();
  const GuideBlocks* blocks = checker.guide_blocks();
  if (grid == nullptr || blocks == nullptr || space.planar())
    return {};
  std::vector<GuidePoint> route =
      find_guide(*grid, *blocks, start, goal, extent.half_extents.maxCoeff());
  double length = 0.0;
  for (std::size_t k = 1; k < route.size(); ++k)
    length += (route[k].point - route[k - 1].point).norm();
  if (route.size() < 2 || !(length > 0.0))
    route.clear();
  return route;
}

bool fits_lengthwise(const std::vector<GuidePoint>& route, const ObjectExtent& extent) {
  if (route.empty())
    return false;
  double narrowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k + 1 < route.size(); ++k)
    narrowest = std::min(narrowest, route[k].clearance);
  return narrowest >= extent.half_extents(1);
}

void GuidedSampler::find() {
  const ObjectExtent extent = checker_.object_extent();
  guide_ = workspace_route(space_, checker_, start_, goal_, extent);
  long_axis_ = extent.axes.col(0);
  least_spread_ = 0.1 * extent.half_extents.maxCoeff();
  double s = 0.0;
  for (std::size_t k = 0; k < guide_->size(); ++k) {
    if (k > 0)
      s += ((*guide_)[k].point - (*guide_)[k - 1].point).norm();
    length_.push_back(s);
  }
  covered_.assign(guide_->size(), false);
  lengthwise_ = fits_lengthwise(*guide_, extent);
  uncovered_ = guide_->size();
}

void GuidedSampler::cover(const Eigen::Vector3d& p) {
  if (!covering())
    return;
  for (std::size_t k = 0; k < guide_->size(); ++k) {
    const GuidePoint& g = (*guide_)[k];
    if (!covered_[k] && (g.point - p).norm() <= std::max(least_spread_, g.clearance)) {
      covered_[k] = true;
      --uncovered_;
    }
  }
}

void GuidedSampler::sample(const SampleRequest& request, std::vector<Target>& out) {
  Rng& rng = *request.rng;
  if (share_ > 0.0 && !guide_)
    find();
  started_ = started_ ||
             (guide_ && !guide_->empty() && request.iteration >= (lengthwise_ ? 0 : kGuideWarmup));
  Config q = space_.sample_uniform(rng);
  if (started_ && uncovered_ == 0 && retire_at_ == 0)
    retire_at_ = 2 * request.iteration;
  const bool guiding = started_ && (uncovered_ > 0 || request.iteration < retire_at_);
  if (guiding && rng.uniform01() < share_)
    along(rng, q);
  out.push_back({q, NodeSource::random});
}

void GuidedSampler::along(Rng& rng, Config& q) const {
  const std::vector<GuidePoint>& g = *guide_;
  const double s = rng.uniform(0.0, length_.back());
  const std::size_t k = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
      std::upper_bound(length_.begin(), length_.end(), s) - length_.begin(), 1,
      static_cast<std::ptrdiff_t>(g.size()) - 1));
  const double span = length_[k] - length_[k - 1];
  const double u = span > 0.0 ? (s - length_[k - 1]) / span : 0.0;
  const Eigen::Vector3d p = g[k - 1].point + u * (g[k].point - g[k - 1].point);
  const double spread =
      std::max(least_spread_, g[k - 1].clearance + u * (g[k].clearance - g[k - 1].clearance));
  const Eigen::Vector3d moved =
      p + spread * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian());
  const Bounds& b = space_.bounds();
  q.t = moved.cwiseMax(b.min).cwiseMin(b.max);
  const Eigen::Vector3d along_route = g[k].point - g[k - 1].point;
  if (!lengthwise_ || !(span > 0.0) || rng.uniform01() >= 0.5)
    return;
  const Eigen::Vector3d axis = (rng.uniform01() < 0.5 ? 1.0 : -1.0) * along_route.normalized();
  q.q = Eigen::AngleAxisd(rng.uniform(-M_PI, M_PI), axis) *
        Eigen::Quaterniond::FromTwoVectors(long_axis_, axis);
}

}  // namespace tandem

#pragma once
// The computer alone's samples, part of them along a workspace guide
// (collision/workspace_guide.hpp): a route of the part's reference point from the start to the
// goal through the workspace's free space, found on the distance grid.
//
// The guide is found at the first iteration (a fraction of a millisecond), or given, found once
// for a run (runs/portfolio.cpp). Where the route is
// open enough for the part lengthwise (its narrowest point, the ends aside, at least the part's
// second-largest half extent from the obstacles: with its longest axis along the route, the part
// roughly fits), the route is a strong hint and guides from the first iteration; elsewhere
// (the part must turn to pass, or cannot pass at all) the trees first spread by uniform samples
// for kGuideWarmup iterations, measured to pay there (README). Then, each iteration:
//   1. with probability `share`, a point drawn uniformly along the guide (by length), moved by a
//      Gaussian of the guide's clearance there (at least a tenth of the part's longest half
//      extent) and kept in the bounds, is the sample's position; its orientation is uniform.
//      Where the part fits the route lengthwise: the point is drawn along the guide's open part
//      only (the segments with an end not yet covered, step 3), the gap the trees have still to
//      close, while there is one (cubicles 41 -> 23 ms, bugtrap within noise; README); and for
//      half of these samples the part's longest axis lies along the route there (either way
//      along it, turned about it uniformly), with the point near the route's centreline: its
//      Gaussian a tenth as wide (Easy 3.0 -> 1.3 ms, cubicles 23 -> 18.5 ms; README);
//   2. otherwise a uniform sample, as without a guide;
//   3. once the trees' nodes have covered every point of the guide (a node within the point's
//      spread), at iteration i, the guide has little more to say: the trees have reached each
//      other along it, or they have not met for another reason (the alpha puzzle, whose
//      difficulty is the part's orientation, not the route). It guides as many iterations again,
//      and from 2i on every sample is uniform.
// A sample is only a target: the planner checks every configuration and motion it adds, so the
// guide changes where the trees grow, never what is valid. Where the grid does not join the start
// to the goal (or there is no grid, or the space is planar), every sample is uniform.
//
// Determinism: every draw comes from the planner's sampling stream, in the planner's order.
// Threading: sample() runs on the planner thread only.

#include <memory>
#include <vector>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/workspace_guide.hpp"
#include "tandem/sampling/target_sampler.hpp"

namespace tandem {

/// The workspace guide from start to goal as GuidedSampler follows it, with the part's extent it
/// was found for.
struct WorkspaceRoute {
  /// Empty where there is none (no distance grid, a planar space, no route on the grid).
  std::vector<GuidePoint> points;
  ObjectExtent extent;  ///< CollisionChecker::object_extent()
};

/// Finds the route (a fraction of a millisecond on the distance grid).
WorkspaceRoute workspace_route(const SE3Space& space, const CollisionChecker& checker,
                               const Eigen::Vector3d& start, const Eigen::Vector3d& goal);

/// Whether the part fits the route lengthwise: the route's narrowest point, its ends aside, at
/// least the part's second-largest half extent from the obstacles (false without a route).
bool fits_lengthwise(const WorkspaceRoute& route);

class GuidedSampler final : public TargetSampler {
 public:
  /// Iterations with uniform samples only, where the route is too narrow for the part lengthwise.
  static constexpr std::uint64_t kGuideWarmup = 200;
  /// The Gaussian's width for a sample turned along the route, as a share of the guide's spread.
  static constexpr double kTurnedSpread = 0.1;

  /// `route`: workspace_route(start, goal) found once for the run (a portfolio's members share
  /// one); null: found at the first sample.
  GuidedSampler(const SE3Space& space, const CollisionChecker& checker, const Config& start,
                const Config& goal, double share,
                std::shared_ptr<const WorkspaceRoute> route = nullptr);
  void sample(const SampleRequest& request, std::vector<Target>& out) override;

  /// Step 3: a node of either tree at p covers the guide's points within their spread of it.
  void cover(const Eigen::Vector3d& p);
  /// Whether cover() still has something to do.
  bool covering() const { return started_ && uncovered_ > 0; }

  /// The guide, once found (empty when there is none).
  const std::vector<GuidePoint>& guide() const { return found_ ? route_->points : kNoGuide; }

 private:
  inline static const std::vector<GuidePoint> kNoGuide;

  /// The route, if not given, and what follows from it (lengths, long axis, spreads).
  void find();
  /// open_length_ from covered_.
  void measure_open();
  /// Step 1's configuration, s along the guide's length (q.q untouched unless it is turned along
  /// the route).
  void along(Rng& rng, Config& q) const;

  const SE3Space& space_;
  const CollisionChecker& checker_;
  Eigen::Vector3d start_;
  Eigen::Vector3d goal_;
  double share_;
  double least_spread_ = 0.0;
  std::shared_ptr<const WorkspaceRoute> route_;
  bool found_ = false;                                    ///< find() has run
  bool lengthwise_ = false;                               ///< fits_lengthwise(*route_), once found
  Eigen::Vector3d long_axis_ = Eigen::Vector3d::UnitX();  ///< the part's, in its frame
  bool started_ = false;        ///< guiding (or retired): its first iteration has come
  std::vector<double> length_;  ///< the guide's length up to each point
  /// The length of the guide's open segments (an end not covered) up to each point.
  std::vector<double> open_length_;
  std::vector<bool> covered_;
  std::size_t uncovered_ = 0;
  std::uint64_t retire_at_ = 0;  ///< step 3's 2i (0 until every point is covered)
};

}  // namespace tandem

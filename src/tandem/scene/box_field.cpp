#include "tandem/scene/box_field.hpp"

#include <cmath>
#include <string>

#include "tandem/core/error.hpp"
#include "tandem/core/rng.hpp"

namespace tandem {
namespace {

constexpr double kRegion = 3.0;     ///< the planner's bounds: a cube of this side (m)
constexpr double kStartGoal = 1.0;  ///< start and goal this far either side of the centre (m)
constexpr double kKeepClear = 0.4;  ///< no box centre nearer the start or the goal than this

Body bar() {
  Body b;
  b.name = "bar";
  b.parts.push_back({Box{Eigen::Vector3d(0.6, 0.05, 0.05)}, Eigen::Isometry3d::Identity()});
  b.color = {0.9, 0.5, 0.1, 1.0};
  return b;
}

}  // namespace

Problem box_field_problem(const BoxFieldOptions& o) {
  if (o.parts == 0)
    throw InputError("box field", "needs at least one part");
  if (!(o.fill > 0.0 && o.fill <= 0.5) || !(o.box_size > 0.0) || !std::isfinite(o.box_size))
    throw InputError("box field", "the fill must be in (0, 0.5] and the box size positive");
  // The cube holds N boxes of mean volume box_size^3 at the fill: side^3 * fill = N * size^3.
  const double side =
      std::max(kRegion, std::cbrt(static_cast<double>(o.parts) / o.fill) * o.box_size);
  const Eigen::Vector3d centre = Eigen::Vector3d::Constant(0.5 * side);
  Problem p{.name = "boxes-" + std::to_string(o.parts),
            .source = "box field",
            .scene = {},
            .space = SE3Space(SpaceKind::se3,
                              {centre.array() - 0.5 * kRegion, centre.array() + 0.5 * kRegion}),
            .start = {},
            .goal = {},
            .hints = {},
            .guide = {},
            .goal_region = std::nullopt};
  p.start.t = centre - Eigen::Vector3d(kStartGoal, 0.0, 0.0);
  p.goal.t = centre + Eigen::Vector3d(kStartGoal, 0.0, 0.0);
  p.scene.object = bar();
  Rng rng(o.seed);
  const SE3Space cube(SpaceKind::se3, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(side)});
  while (p.scene.obstacles.size() < o.parts) {
    const Config at = cube.sample_uniform(rng);  // a place and a uniform orientation
    if ((at.t - p.start.t).norm() < kKeepClear || (at.t - p.goal.t).norm() < kKeepClear)
      continue;
    Body b;
    b.name = "box " + std::to_string(p.scene.obstacles.size());
    const Eigen::Vector3d size(o.box_size * rng.uniform(0.5, 1.5),
                               o.box_size * rng.uniform(0.5, 1.5),
                               o.box_size * rng.uniform(0.5, 1.5));
    b.parts.push_back({Box{size}, at.pose()});
    p.scene.obstacles.push_back(std::move(b));
  }
  return p;
}

}  // namespace tandem

#pragma once
// A goal region: "take this part out". The object is in it when the whole part is outside a box
// grown by a margin (the assembly's bounding box): no part of it is within the margin of the box.
//
// The test: the bounding box of the object's vertices, posed by the configuration, does not meet
// the grown box. A part diagonally beside a corner of the box may count as inside: conservative.

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "tandem/space/config.hpp"

namespace tandem {

struct GoalRegion {
  Eigen::Vector3d min;  ///< the box, grown by the margin
  Eigen::Vector3d max;
  double margin = 0.0;
  std::vector<Eigen::Vector3d> points;  ///< the object's vertices, in the object frame

  /// Whether the object posed at q is in the region.
  bool contains(const Config& q) const;
  /// The bounding box (min, max) of the object's points posed at q, in the world frame.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> posed_box(const Config& q) const;
};

}  // namespace tandem

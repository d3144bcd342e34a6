#pragma once
// Workspace passages: the tubes of free space that a part can pass only along their axis, found on
// the distance grid of the obstacles.
//
// A tube's axis is a ridge of the distance to the obstacles: across the tube the distance is
// largest on the axis (two directions of negative curvature), along it the distance changes
// little. At a grid cell whose bound is at least its neighbours' along two or more of the grid's
// axes, the Hessian of the bound (central differences over the 18 nearest cells) is decomposed:
// the cell is on a tube's axis when its two smallest eigenvalues are clearly negative and the third
// is much closer to zero; the axis's direction is the third eigenvector. Slots (one negative
// eigenvalue) and chambers (three) are not tubes. Only tubes narrower than `max_clearance` count:
// wider ones are open space for the part.
//
// The grid's values are lower bounds in eighths of a cell, so the passages are approximate: what
// uses them (planning/passage_islands.hpp) checks every configuration it makes of them.
//
// Threading: a pure function of an immutable grid.

#include <Eigen/Core>
#include <vector>

#include "tandem/collision/distance_grid.hpp"

namespace tandem {

struct Passage {
  Eigen::Vector3d point;      ///< a cell centre on the tube's axis
  Eigen::Vector3d direction;  ///< the axis's direction (unit; its sign is arbitrary)
  double clearance = 0.0;     ///< the grid's bound at the point
};

/// The cells of the grid on the axis of a tube narrower than max_clearance, in cell order.
std::vector<Passage> find_passages(const DistanceGrid& grid, double max_clearance);

}  // namespace tandem

#pragma once
// A workspace guide: a route for the part's reference point from the start to the goal through the
// free space of the workspace, found on the distance grid of the obstacles, along which the
// computer alone samples (sampling/guided_sampler.hpp).
//
// The idea is workspace-guided sampling: the workspace says where a route may run (Kurniawati &
// Hsu, "Workspace importance sampling", IROS 2004; Plaku, Kavraki & Vardi, "Motion planning with
// dynamics by a synergistic combination of layers of planning" (Syclop), IEEE TRO 2010, which
// leads a tree along a lead of workspace regions). Here:
//   1. the grid, inside the space's bounds, is coarsened to at most kMaxGuideBlocks blocks; a
//      block stands for its most open cell (its largest bound), so a hole narrower than a block
//      still joins its neighbours;
//   2. the bottleneck: the largest clearance b such that the start's and the goal's blocks are
//      joined (26-neighbours) through blocks at least b open, the two end blocks not counted;
//      blocks the grid does not know to be free (bound <= 0) are walls: no route passes them;
//   3. the route: the shortest path (Dijkstra) through blocks at least b / 2 open, each move
//      costing its length times 1 + open / c, c its less open block's clearance (at most `open`,
//      the part's longest half extent): open rooms are preferred to corridors along walls;
//   4. the guide: the start's position, the route's cells' centres, the goal's position.
// The grid's bounds are conservative and the blocks approximate, so the guide is only a hint: a
// route may be one the part cannot take (it turns, it is too big); what uses it checks everything.
//
// Threading: a pure function of an immutable grid.

#include <Eigen/Core>
#include <vector>

#include "tandem/collision/distance_grid.hpp"
#include "tandem/space/bounds.hpp"

namespace tandem {

struct GuidePoint {
  Eigen::Vector3d point;
  double clearance = 0.0;  ///< the grid's bound there (0 at the ends if it knows nothing)
};

/// Step 1's largest number of blocks.
inline constexpr int kMaxGuideBlocks = 1 << 15;

/// The route from `from` to `to` through the cells whose centres are in `bounds`, or nothing when
/// the grid does not join them there.
std::vector<GuidePoint> find_guide(const DistanceGrid& grid, const Bounds& bounds,
                                   const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                   double open);

}  // namespace tandem

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
//   3. the route: the shortest path (A*) through blocks at least b / 2 open, each move
//      costing its length times 1 + open / c, c its less open block's clearance (at most `open`,
//      the part's longest half extent): open rooms are preferred to corridors along walls;
//   4. the guide: the start's position, the route's cells' centres, the goal's position.
// The grid's bounds are conservative and the blocks approximate, so the guide is only a hint: a
// route may be one the part cannot take (it turns, it is too big); what uses it checks everything.
//
// Step 1 depends on the grid and the bounds only, not on the start and goal: GuideBlocks is built
// once per problem with the grid (CollisionChecker::guide_blocks), before a planner's clock starts,
// and every later route (steps 2-4) starts from it.
//
// Threading: GuideBlocks is immutable once built; find_guide is a pure function of it and the grid.

#include <Eigen/Core>
#include <array>
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

/// Step 1: the grid's cells whose centres are in `bounds`, coarsened to at most kMaxGuideBlocks
/// blocks, each standing for its most open cell.
class GuideBlocks {
 public:
  GuideBlocks(const DistanceGrid& grid, const Bounds& bounds);

  int size() const { return static_cast<int>(clearance_.size()); }
  /// Blocks along x, y and z; block (x, y, z) has index (z dims.y + y) dims.x + x.
  const Eigen::Vector3i& dims() const { return dims_; }
  /// The block holding p, or -1 outside the grid.
  int block_of(const DistanceGrid& grid, const Eigen::Vector3d& p) const;
  /// Its most open cell's bound (-inf outside the bounds) and that cell's centre.
  double clearance(int i) const { return clearance_[static_cast<std::size_t>(i)]; }
  const Eigen::Vector3d& centre(int i) const { return centre_[static_cast<std::size_t>(i)]; }
  /// Free space, as far as the grid knows: a positive bound.
  bool open(int i) const { return clearance(i) > 0.0; }
  /// Its most open cell's value in the grid (0-255: clearance(i) grows with it), or -1 outside
  /// the bounds.
  int level(int i) const { return level_[static_cast<std::size_t>(i)]; }
  /// The clearance of the blocks at `level` (one of theirs).
  double level_clearance(int level) const {
    return level_clearance_[static_cast<std::size_t>(level)];
  }
  /// Visits the 26 neighbours of block i that are inside the coarse grid.
  template <class Visit>
  void for_neighbours(int i, Visit visit) const;

 private:
  int index(const Eigen::Vector3i& b) const {
    return (b.z() * dims_.y() + b.y()) * dims_.x() + b.x();
  }
  Eigen::Vector3i cell(int i) const {
    return {i % dims_.x(), (i / dims_.x()) % dims_.y(), i / (dims_.x() * dims_.y())};
  }
  bool inside(const Eigen::Vector3i& b) const {
    return (b.array() >= 0).all() && (b.array() < dims_.array()).all();
  }

  Eigen::Vector3i dims_;
  int factor_ = 1;
  std::vector<double> clearance_;
  std::vector<int> level_;
  std::array<double, 256> level_clearance_{};
  std::vector<Eigen::Vector3d> centre_;
  std::array<int, 26> offsets_{};  ///< index(c + d) - index(c) for the 26 d, z outermost
};

template <class Visit>
void GuideBlocks::for_neighbours(int i, Visit visit) const {
  const Eigen::Vector3i c = cell(i);
  if ((c.array() > 0).all() && (c.array() < dims_.array() - 1).all()) {
    for (int offset : offsets_)  // all 26 inside, in the order of the loops below
      visit(i + offset);
    return;
  }
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Eigen::Vector3i n = c + Eigen::Vector3i(dx, dy, dz);
        if ((dx | dy | dz) != 0 && inside(n))
          visit(index(n));
      }
    }
  }
}

/// Steps 2-4: the route from `from` to `to` through the blocks (of this grid), or nothing when
/// the grid does not join them there.
std::vector<GuidePoint> find_guide(const DistanceGrid& grid, const GuideBlocks& blocks,
                                   const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                   double open);

}  // namespace tandem

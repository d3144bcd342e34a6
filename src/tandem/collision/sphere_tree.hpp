#pragma once
// A hierarchy of spheres that enclose the moving object, for the distance grid's pre-filter.
//
// The leaves enclose pieces of the object's surface (its triangles, split until each fits a
// sphere of the leaf radius) or whole solid primitives; each inner sphere encloses its children.
// The clearance of the object at a pose is at least the smallest, over the leaves, of the grid's
// lower bound at the leaf's centre minus its radius; an inner sphere whose own bound is already
// large enough stands for all of its leaves (clearance_at()).
//
// Threading: immutable once built; any number of threads may query it.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "tandem/collision/distance_grid.hpp"

namespace tandem {

class SphereTree {
 public:
  struct Ball {
    Eigen::Vector3d centre;
    double radius;
  };

  /// Encloses the triangles (a surface) and the boxes (solids), all in the object frame, with
  /// leaves of at most `leaf_radius` where a triangle allows it.
  SphereTree(const std::vector<DistanceGrid::Triangle>& triangles,
             const std::vector<DistanceGrid::Box>& solids, double leaf_radius);

  /// A lower bound on the distance between the object at pose X_WO and the grid's obstacles when
  /// that bound is at least `enough`; the bound is capped at `enough_for_all` (>= enough), beyond
  /// which the hierarchy is not opened. Returns a value < enough (without finishing) as soon as
  /// a leaf shows that the grid cannot certify `enough`, or when more than `budget` inner
  /// spheres would have to be opened. Adds the inner spheres it opened to `opened` when given.
  double clearance_at(const DistanceGrid& grid, const Eigen::Isometry3d& X_WO, double enough,
                      double enough_for_all, int budget, std::uint64_t* opened = nullptr) const;

  std::size_t leaf_count() const { return leaves_; }

 private:
  struct Node {
    Eigen::Vector3d centre;
    double radius;
    int first_child;  ///< -1 for a leaf; the second child follows the first's subtree
    int second_child;
  };
  int build(std::vector<Ball>& balls, std::size_t begin, std::size_t end);

  std::vector<Node> nodes_;
  std::size_t leaves_ = 0;
};

}  // namespace tandem

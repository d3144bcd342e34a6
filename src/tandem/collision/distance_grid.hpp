#pragma once
// A distance grid of the obstacles, built once: a conservative lower bound on the distance from a
// point to every obstacle, in a few memory reads (the pre-filter of VAMP-style checkers, carried
// to meshes without giving up exactness).
//
// How it is built: every cell of a regular grid (spacing h) that an obstacle's triangle may touch
// is marked (triangles are split until their bounding box is at most a cell, then every cell the
// box overlaps is marked); solid primitives mark every cell their bounding box overlaps. The exact
// Euclidean distance transform of the marked cells' centres follows (Felzenszwalb and
// Huttenlocher, "Distance transforms of sampled functions", 2012: separable, one lower envelope of
// parabolas per row).
//
// Why it is a lower bound: every obstacle point s lies in a marked cell, within h sqrt(3) / 2 of
// its centre m; so for a point p and the centre v of p's cell,
//   |p - s| >= |p - m| - h sqrt(3)/2 >= |v - m| - |p - v| - h sqrt(3)/2 >= EDT(v) - |p - v| - h sqrt(3)/2.
// Marking too many cells only lowers the bound. Obstacles outside the grid mark the cells their
// clamped bounding box overlaps: clamping onto a box moves no point closer to a point inside it.
// Points outside the grid get 0 (no information).
//
// OpenVDB's mesh-to-volume was considered: beyond the first voxels it propagates distances to a
// neighbour's closest triangle, which can be farther than the true closest one, an upper bound.
//
// Threading: immutable once built; any number of threads may query it.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tandem {

class DistanceGrid {
 public:
  struct Triangle {
    Eigen::Vector3d a, b, c;
  };
  struct Box {
    Eigen::Vector3d min, max;
  };

  /// The two halves of t, split at the midpoint of its longest edge (they cover t).
  static std::array<Triangle, 2> split_at_longest_edge(const Triangle& t);

  /// A grid over `region` (grown by a cell on every side) with cells of `spacing`, or coarser if
  /// that would exceed `max_cells`. The obstacles are triangles (surfaces, as FCL's meshes) and
  /// boxes that enclose solid primitives.
  DistanceGrid(const Box& region, double spacing, const std::vector<Triangle>& triangles,
               const std::vector<Box>& solids, std::size_t max_cells = std::size_t{1} << 24);

  /// A lower bound on the distance from p to every obstacle (negative or 0 when nothing is known).
  double lower_bound(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d u = (p - origin_) * inverse_spacing_;
    if (!(u.array() >= 0.0).all() || !(u.array() < dims_.cast<double>().array()).all())
      return 0.0;
    const Eigen::Vector3i i = u.cast<int>();
    const Eigen::Vector3d centre = origin_ + (i.cast<double>().array() + 0.5).matrix() * spacing_;
    return distance_[index(i)] * quantum_ - (p - centre).norm() - slack_;
  }

  /// The bound at the centre of cell i (inside dims()): the grid's value there, less the slack.
  double centre_bound(const Eigen::Vector3i& i) const {
    return distance_[index(i)] * quantum_ - slack_;
  }
  Eigen::Vector3d centre(const Eigen::Vector3i& i) const {
    return origin_ + (i.cast<double>().array() + 0.5).matrix() * spacing_;
  }

  /// The stored values, cell (x, y, z) at (z * dims.y + y) * dims.x + x: the centre's distance
  /// in quanta, before the slack is taken off (centre_bound = value * quantum - slack).
  const std::vector<std::uint8_t>& values() const { return distance_; }
  double quantum() const { return quantum_; }
  double slack() const { return slack_; }

  double spacing() const { return spacing_; }
  const Eigen::Vector3i& dims() const { return dims_; }
  std::size_t marked_cells() const { return marked_; }

 private:
  std::size_t index(const Eigen::Vector3i& i) const {
    const auto [x, y, z] =
        std::array<std::size_t, 3>{static_cast<std::size_t>(i.x()), static_cast<std::size_t>(i.y()),
                                   static_cast<std::size_t>(i.z())};
    return (z * static_cast<std::size_t>(dims_.y()) + y) * static_cast<std::size_t>(dims_.x()) + x;
  }
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const;
  void mark_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  void mark_triangle(const Triangle& t, int depth);
  void transform();

  Eigen::Vector3d origin_;
  Eigen::Vector3i dims_;
  double spacing_ = 0.0;
  double inverse_spacing_ = 0.0;
  double slack_ = 0.0;  ///< h sqrt(3) / 2, plus a rounding margin
  std::size_t marked_ = 0;
  /// The distances, in quanta of an eighth of a cell, rounded down (so a bound stays a bound) and
  /// capped at 255 (32 cells): one byte a cell keeps the grid in the caches, where a query's
  /// reads are; four were three times slower on Easy (12 MB, a cache miss a read).
  double quantum_ = 0.0;
  std::vector<std::uint8_t> distance_;
};

}  // namespace tandem

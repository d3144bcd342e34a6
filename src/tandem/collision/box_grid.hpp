#pragma once
// A uniform grid over a fixed set of axis-aligned boxes, for the question "which boxes overlap this
// box?" in a time that does not grow with the number of boxes where the boxes are spread about
// evenly (a box field, an assembly of many small parts). The cells are about the size of the
// median box; each box is listed in the cells it covers; a query looks at the cells its box covers
// and reports each overlapping box once, in the cell that holds the lower corner of the two boxes'
// intersection (no marks, so no state per query). Boxes much larger than a cell are kept apart and
// tested on every query; a query box covering more cells than there are boxes scans the boxes.
//
// build() refuses boxes that a grid would serve badly (crowded cells: a query would still meet
// many boxes), so that the caller keeps its tree for them.
//
// Threading: immutable once built; any number of threads may query it.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace tandem {

class BoxGrid {
 public:
  struct Box {
    Eigen::Vector3d min;
    Eigen::Vector3d max;
  };

  /// A box spanning more cells than this is tested on every query instead of being listed.
  static constexpr std::size_t kLargeCells = 64;
  /// Refused when a query, on average, would meet more listed boxes in a cell than this, or when
  /// more boxes than this are large.
  static constexpr double kCrowded = 16.0;

  /// The grid over `boxes` (a box's index is its position), or nothing when a grid would serve
  /// them badly.
  static std::optional<BoxGrid> build(const std::vector<Box>& boxes);

  /// Calls visit(i) once for every box i that overlaps `query` (touching counts), until a call
  /// returns true; returns whether one did. The order is the grid's, not the boxes'.
  template <class Visit>
  bool overlapping(const Box& query, Visit&& visit) const {
    const Cell lo = cell_of(query.min), hi = cell_of(query.max);
    if (span(lo, hi) > boxes_.size())
      return scan(query, visit);
    for (const std::uint32_t i : large_) {
      if (overlaps(boxes_[i], query) && visit(std::size_t{i}))
        return true;
    }
    return each_cell(lo, hi, [&](const Cell& cell) { return visit_cell(cell, query, visit); });
  }

  std::size_t cell_count() const { return start_.size() - 1; }
  std::size_t large_count() const { return large_.size(); }

 private:
  using Cell = std::array<int, 3>;

  static bool overlaps(const Box& a, const Box& b) {
    return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
  }

  int axis_cell(double x, std::size_t axis) const {
    const double c = (x - origin_[static_cast<Eigen::Index>(axis)]) * inverse_size_;
    if (!(c >= 1.0))  // (NaN too)
      return 0;
    const int last = cells_[axis] - 1;
    return c >= last ? last : static_cast<int>(c);
  }
  Cell cell_of(const Eigen::Vector3d& p) const {
    return {axis_cell(p.x(), 0), axis_cell(p.y(), 1), axis_cell(p.z(), 2)};
  }
  static std::size_t span(const Cell& lo, const Cell& hi) {
    return std::size_t(hi[0] - lo[0] + 1) * std::size_t(hi[1] - lo[1] + 1) *
           std::size_t(hi[2] - lo[2] + 1);
  }
  std::size_t index(const Cell& c) const {
    return (std::size_t(c[2]) * std::size_t(cells_[1]) + std::size_t(c[1])) *
               std::size_t(cells_[0]) +
           std::size_t(c[0]);
  }

  /// Calls f(cell) for the cells from lo to hi, until a call returns true; returns whether one did.
  template <class F>
  static bool each_cell(const Cell& lo, const Cell& hi, F&& f) {
    for (int z = lo[2]; z <= hi[2]; ++z) {
      for (int y = lo[1]; y <= hi[1]; ++y) {
        for (int x = lo[0]; x <= hi[0]; ++x) {
          if (f(Cell{x, y, z}))
            return true;
        }
      }
    }
    return false;
  }

  /// The boxes listed in `cell` that overlap `query` and whose intersection with it starts there.
  template <class Visit>
  bool visit_cell(const Cell& cell, const Box& query, Visit& visit) const {
    const std::size_t k = index(cell);
    for (std::uint32_t n = start_[k]; n < start_[k + 1]; ++n) {
      const std::uint32_t i = items_[n];
      const Box& b = boxes_[i];
      if (!overlaps(b, query) || cell_of(b.min.cwiseMax(query.min)) != cell)
        continue;
      if (visit(std::size_t{i}))
        return true;
    }
    return false;
  }

  /// Fills start_, items_ and large_ once the cells are set.
  void list_boxes();
  /// How many listed boxes share a listed box's cell, on average over the listed boxes.
  double crowding() const;

  template <class Visit>
  bool scan(const Box& query, Visit& visit) const {
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      if (overlaps(boxes_[i], query) && visit(i))
        return true;
    }
    return false;
  }

  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double inverse_size_ = 1.0;
  std::array<int, 3> cells_{1, 1, 1};
  std::vector<Box> boxes_;
  std::vector<std::uint32_t> start_;  ///< per cell, where its boxes start in items_ (and an end)
  std::vector<std::uint32_t> items_;  ///< the listed boxes, cell after cell
  std::vector<std::uint32_t> large_;  ///< the boxes tested on every query
};

}  // namespace tandem

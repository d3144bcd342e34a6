#include "tandem/collision/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tandem {
namespace {

using Box = BoxGrid::Box;

/// The median of the boxes' largest extents: most boxes then cover one to eight cells.
double median_extent(const std::vector<Box>& boxes) {
  std::vector<double> extents;
  extents.reserve(boxes.size());
  for (const Box& b : boxes)
    extents.push_back((b.max - b.min).maxCoeff());
  auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
  std::nth_element(extents.begin(), middle, extents.end());
  return *middle;
}

double cells_along(double length, double size) {
  return std::max(1.0, std::ceil(length / size));
}

/// The cell size: the median extent, made larger while the grid would have more than about four
/// cells per box (scattered boxes: the memory stays proportional to their number).
double cell_size(const std::vector<Box>& boxes, const Eigen::Vector3d& extent) {
  const double cap = 4.0 * static_cast<double>(boxes.size()) + 64.0;
  double size = std::max({median_extent(boxes), 1e-3 * extent.maxCoeff(), 1e-12});
  const auto cells = [&](double s) {
    return cells_along(extent.x(), s) * cells_along(extent.y(), s) * cells_along(extent.z(), s);
  };
  while (cells(size) > cap)
    size *= 1.25;
  return size;
}

}  // namespace

std::optional<BoxGrid> BoxGrid::build(const std::vector<Box>& boxes) {
  if (boxes.empty() || boxes.size() >= std::numeric_limits<std::uint32_t>::max())
    return std::nullopt;
  Eigen::Vector3d lo = boxes.front().min, hi = boxes.front().max;
  for (const Box& b : boxes) {
    if (!b.min.allFinite() || !b.max.allFinite())
      return std::nullopt;
    lo = lo.cwiseMin(b.min);
    hi = hi.cwiseMax(b.max);
  }
  const Eigen::Vector3d extent = hi - lo;
  if (!extent.allFinite())  // (boxes near the ends of the doubles' range)
    return std::nullopt;
  BoxGrid grid;
  grid.boxes_ = boxes;
  grid.origin_ = lo;
  const double size = cell_size(boxes, extent);
  grid.inverse_size_ = 1.0 / size;
  grid.cells_ = {static_cast<int>(cells_along(extent.x(), size)),
                 static_cast<int>(cells_along(extent.y(), size)),
                 static_cast<int>(cells_along(extent.z(), size))};
  grid.list_boxes();
  if (grid.crowding() > kCrowded || static_cast<double>(grid.large_.size()) > kCrowded)
    return std::nullopt;
  return grid;
}

void BoxGrid::list_boxes() {
  const std::size_t cells =
      std::size_t(cells_[0]) * std::size_t(cells_[1]) * std::size_t(cells_[2]);
  std::vector<std::uint32_t> count(cells + 1, 0);
  const auto for_cells = [&](const Box& b, auto&& f) {
    each_cell(cell_of(b.min), cell_of(b.max), [&](const Cell& c) {
      f(index(c));
      return false;
    });
  };
  std::vector<bool> large(boxes_.size());
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    large[i] = span(cell_of(boxes_[i].min), cell_of(boxes_[i].max)) > kLargeCells;
    if (large[i])
      large_.push_back(static_cast<std::uint32_t>(i));
    else
      for_cells(boxes_[i], [&](std::size_t k) { ++count[k + 1]; });
  }
  for (std::size_t k = 0; k < cells; ++k)
    count[k + 1] += count[k];
  start_ = count;
  items_.resize(start_.back());
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (!large[i])
      for_cells(boxes_[i],
                [&](std::size_t k) { items_[count[k]++] = static_cast<std::uint32_t>(i); });
  }
}

double BoxGrid::crowding() const {
  double listed = 0.0, met = 0.0;
  for (std::size_t k = 0; k + 1 < start_.size(); ++k) {
    const double n = start_[k + 1] - start_[k];
    listed += n;
    met += n * n;
  }
  return listed > 0.0 ? met / listed : 0.0;
}

}  // namespace tandem

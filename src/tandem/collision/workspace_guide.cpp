#include "tandem/collision/workspace_guide.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>

namespace tandem {
namespace {

/// Step 1: the coarse grid; a block stands for its most open cell.
struct Blocks {
  Eigen::Vector3i dims;
  int factor = 1;
  std::vector<double> clearance;
  std::vector<Eigen::Vector3d> centre;

  int index(const Eigen::Vector3i& b) const {
    return (b.z() * dims.y() + b.y()) * dims.x() + b.x();
  }
  Eigen::Vector3i cell(int i) const {
    return {i % dims.x(), (i / dims.x()) % dims.y(), i / (dims.x() * dims.y())};
  }
  /// Free space, as far as the grid knows: a positive bound (blocks outside the bounds have -inf).
  bool open(int i) const { return clearance[static_cast<std::size_t>(i)] > 0.0; }
  bool inside(const Eigen::Vector3i& b) const {
    return (b.array() >= 0).all() && (b.array() < dims.array()).all();
  }
};

Blocks coarsen(const DistanceGrid& grid, const Bounds& bounds) {
  const Eigen::Vector3i d = grid.dims();
  const double cells = static_cast<double>(d.x()) * d.y() * d.z();
  Blocks b;
  b.factor = std::max(1, static_cast<int>(std::ceil(std::cbrt(cells / kMaxGuideBlocks))));
  b.dims = (d.array() + b.factor - 1) / b.factor;
  const auto n = static_cast<std::size_t>(b.dims.prod());
  std::vector<int> best(n, -1);
  std::vector<int> best_cell(n, 0);
  // Only the cells whose centres are in the bounds: the route stays where the part may be.
  const Eigen::Vector3d first = grid.centre(Eigen::Vector3i::Zero());
  const Eigen::Vector3i lo =
      ((bounds.min - first) / grid.spacing()).array().ceil().cast<int>().max(0);
  const Eigen::Vector3i hi =
      ((bounds.max - first) / grid.spacing()).array().floor().cast<int>().min(d.array() - 1);
  const std::vector<std::uint8_t>& v = grid.values();
  for (int z = lo.z(); z <= hi.z(); ++z) {
    for (int y = lo.y(); y <= hi.y(); ++y) {
      const int row = ((z / b.factor) * b.dims.y() + y / b.factor) * b.dims.x();
      const int cells_row = (z * d.y() + y) * d.x();
      for (int x0 = lo.x(); x0 <= hi.x(); x0 += b.factor - (x0 % b.factor)) {
        // The cells of one block along x.
        const auto k = static_cast<std::size_t>(row + x0 / b.factor);
        const int x1 = std::min(hi.x() + 1, (x0 / b.factor + 1) * b.factor);
        for (int i = cells_row + x0; i < cells_row + x1; ++i) {
          if (v[static_cast<std::size_t>(i)] > best[k]) {
            best[k] = v[static_cast<std::size_t>(i)];
            best_cell[k] = i;
          }
        }
      }
    }
  }
  b.clearance.resize(n);
  b.centre.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int i = best_cell[k];
    if (best[k] < 0) {  // outside the bounds
      b.clearance[k] = -std::numeric_limits<double>::infinity();
      continue;
    }
    const Eigen::Vector3i c(i % d.x(), (i / d.x()) % d.y(), i / (d.x() * d.y()));
    b.clearance[k] = grid.centre_bound(c);
    b.centre[k] = grid.centre(c);
  }
  return b;
}

/// The block holding p, or -1 outside the grid.
int block_of(const DistanceGrid& grid, const Blocks& b, const Eigen::Vector3d& p) {
  const Eigen::Vector3d u = (p - grid.centre(Eigen::Vector3i::Zero())) / grid.spacing();
  const Eigen::Vector3i cell = (u.array() + 0.5).floor().cast<int>();
  if (!(cell.array() >= 0).all() || !(cell.array() < grid.dims().array()).all())
    return -1;
  return b.index(cell / b.factor);
}

/// Visits the 26 neighbours of block i that are inside the coarse grid.
template <class Visit>
void for_neighbours(const Blocks& b, int i, Visit visit) {
  const Eigen::Vector3i c = b.cell(i);
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Eigen::Vector3i n = c + Eigen::Vector3i(dx, dy, dz);
        if ((dx | dy | dz) != 0 && b.inside(n))
          visit(b.index(n));
      }
    }
  }
}

/// Step 2: the largest clearance joining `from` to `to` (the two ends not counted); -inf if none
/// joins them.
double bottleneck(const Blocks& b, int from, int to) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  std::vector<double> width(b.clearance.size(), kNone);
  std::priority_queue<std::pair<double, int>> open;  // widest first
  width[static_cast<std::size_t>(from)] = std::numeric_limits<double>::infinity();
  open.push({width[static_cast<std::size_t>(from)], from});
  while (!open.empty()) {
    // (Plain copies, not a structured binding: clang 14, the fuzzing build's compiler, cannot
    // capture bindings in a lambda.)
    const double w = open.top().first;
    const int i = open.top().second;
    open.pop();
    if (i == to)
      return w;
    if (w < width[static_cast<std::size_t>(i)])
      continue;
    for_neighbours(b, i, [&](int n) {
      if (n != to && !b.open(n))
        return;
      const double c = n == to ? w : std::min(w, b.clearance[static_cast<std::size_t>(n)]);
      if (c > width[static_cast<std::size_t>(n)]) {
        width[static_cast<std::size_t>(n)] = c;
        open.push({c, n});
      }
    });
  }
  return kNone;
}

/// Step 3: the cheapest route from `from` to `to` through blocks at least `least` open.
std::vector<int> route(const Blocks& b, int from, int to, double least, double open_width) {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<double> cost(b.clearance.size(), kFar);
  std::vector<int> parent(b.clearance.size(), -1);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;  // cheapest first
  cost[static_cast<std::size_t>(from)] = 0.0;
  queue.push({0.0, from});
  const double floor = 1e-3 * open_width;
  while (!queue.empty()) {
    const double g = queue.top().first;
    const int i = queue.top().second;
    queue.pop();
    if (i == to)
      break;
    if (g > cost[static_cast<std::size_t>(i)])
      continue;
    const Eigen::Vector3d& p = b.centre[static_cast<std::size_t>(i)];
    for_neighbours(b, i, [&](int n) {
      const double cn = b.clearance[static_cast<std::size_t>(n)];
      if (n != to && (!b.open(n) || cn < least))
        return;
      const double c =
          std::clamp(std::min(cn, b.clearance[static_cast<std::size_t>(i)]), floor, open_width);
      const double step =
          (b.centre[static_cast<std::size_t>(n)] - p).norm() * (1.0 + open_width / c);
      if (g + step < cost[static_cast<std::size_t>(n)]) {
        cost[static_cast<std::size_t>(n)] = g + step;
        parent[static_cast<std::size_t>(n)] = i;
        queue.push({g + step, n});
      }
    });
  }
  std::vector<int> blocks;
  if (cost[static_cast<std::size_t>(to)] == kFar)
    return blocks;
  for (int i = to; i != -1; i = parent[static_cast<std::size_t>(i)])
    blocks.push_back(i);
  std::reverse(blocks.begin(), blocks.end());
  return blocks;
}

}  // namespace

std::vector<GuidePoint> find_guide(const DistanceGrid& grid, const Bounds& bounds,
                                   const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                   double open) {
  const Blocks b = coarsen(grid, bounds);
  const int first = block_of(grid, b, from);
  const int last = block_of(grid, b, to);
  if (first < 0 || last < 0 || !(open > 0.0))
    return {};
  // Joined through each other or a neighbour, the ends leave no bottleneck: no bound then.
  const double width = bottleneck(b, first, last);
  if (width == -std::numeric_limits<double>::infinity())
    return {};
  const double least = std::isfinite(width) ? 0.5 * width : -width;
  const std::vector<int> blocks = route(b, first, last, least, open);
  if (blocks.empty())
    return {};
  std::vector<GuidePoint> guide{{from, std::max(0.0, grid.lower_bound(from))}};
  for (std::size_t k = 1; k + 1 < blocks.size(); ++k) {
    const auto i = static_cast<std::size_t>(blocks[k]);
    guide.push_back({b.centre[i], b.clearance[i]});
  }
  guide.push_back({to, std::max(0.0, grid.lower_bound(to))});
  return guide;
}

}  // namespace tandem

#include "tandem/collision/workspace_guide.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>

namespace tandem {

GuideBlocks::GuideBlocks(const DistanceGrid& grid, const Bounds& bounds) {
  const Eigen::Vector3i d = grid.dims();
  const double cells = static_cast<double>(d.x()) * d.y() * d.z();
  factor_ = std::max(1, static_cast<int>(std::ceil(std::cbrt(cells / kMaxGuideBlocks))));
  dims_ = (d.array() + factor_ - 1) / factor_;
  const auto n = static_cast<std::size_t>(dims_.prod());
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
      const int row = ((z / factor_) * dims_.y() + y / factor_) * dims_.x();
      const int cells_row = (z * d.y() + y) * d.x();
      for (int x0 = lo.x(); x0 <= hi.x(); x0 += factor_ - (x0 % factor_)) {
        // The cells of one block along x.
        const auto k = static_cast<std::size_t>(row + x0 / factor_);
        const int x1 = std::min(hi.x() + 1, (x0 / factor_ + 1) * factor_);
        for (int i = cells_row + x0; i < cells_row + x1; ++i) {
          if (v[static_cast<std::size_t>(i)] > best[k]) {
            best[k] = v[static_cast<std::size_t>(i)];
            best_cell[k] = i;
          }
        }
      }
    }
  }
  clearance_.resize(n);
  centre_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int i = best_cell[k];
    if (best[k] < 0) {  // outside the bounds
      clearance_[k] = -std::numeric_limits<double>::infinity();
      continue;
    }
    const Eigen::Vector3i c(i % d.x(), (i / d.x()) % d.y(), i / (d.x() * d.y()));
    clearance_[k] = grid.centre_bound(c);
    centre_[k] = grid.centre(c);
  }
  std::size_t k = 0;
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx | dy | dz) != 0)
          offsets_[k++] = (dz * dims_.y() + dy) * dims_.x() + dx;
      }
    }
  }
}

int GuideBlocks::block_of(const DistanceGrid& grid, const Eigen::Vector3d& p) const {
  const Eigen::Vector3d u = (p - grid.centre(Eigen::Vector3i::Zero())) / grid.spacing();
  const Eigen::Vector3i cell = (u.array() + 0.5).floor().cast<int>();
  if (!(cell.array() >= 0).all() || !(cell.array() < grid.dims().array()).all())
    return -1;
  return index(cell / factor_);
}

namespace {

/// Step 2: the largest clearance joining `from` to `to` (the two ends not counted); -inf if none
/// joins them.
double bottleneck(const GuideBlocks& b, int from, int to) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  std::vector<double> width(static_cast<std::size_t>(b.size()), kNone);
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
    b.for_neighbours(i, [&](int n) {
      if (n != to && !b.open(n))
        return;
      const double c = n == to ? w : std::min(w, b.clearance(n));
      if (c > width[static_cast<std::size_t>(n)]) {
        width[static_cast<std::size_t>(n)] = c;
        open.push({c, n});
      }
    });
  }
  return kNone;
}

/// Step 3: the cheapest route from `from` to `to` through blocks at least `least` open.
std::vector<int> route(const GuideBlocks& b, int from, int to, double least, double open_width) {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<double> cost(static_cast<std::size_t>(b.size()), kFar);
  std::vector<int> parent(static_cast<std::size_t>(b.size()), -1);
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
    const Eigen::Vector3d& p = b.centre(i);
    b.for_neighbours(i, [&](int n) {
      const double cn = b.clearance(n);
      if (n != to && (!b.open(n) || cn < least))
        return;
      const double c = std::clamp(std::min(cn, b.clearance(i)), floor, open_width);
      const double step = (b.centre(n) - p).norm() * (1.0 + open_width / c);
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

std::vector<GuidePoint> find_guide(const DistanceGrid& grid, const GuideBlocks& b,
                                   const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                   double open) {
  const int first = b.block_of(grid, from);
  const int last = b.block_of(grid, to);
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
  for (std::size_t k = 1; k + 1 < blocks.size(); ++k)
    guide.push_back({b.centre(blocks[k]), b.clearance(blocks[k])});
  guide.push_back({to, std::max(0.0, grid.lower_bound(to))});
  return guide;
}

}  // namespace tandem

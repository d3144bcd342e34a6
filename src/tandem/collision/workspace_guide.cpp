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
  level_ = best;
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
    level_clearance_[static_cast<std::size_t>(best[k])] = clearance_[k];
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
/// joins them. The widest-first search runs on the blocks' levels (a clearance grows with its
/// level, and there are 256), with one stack of blocks per level instead of a heap: the widest
/// block is on the highest stack that is not empty, and no block is pushed above the one popped.
double bottleneck(const GuideBlocks& b, int from, int to) {
  constexpr int kEnds = 256;  // the level of `from`: wider than any block
  std::vector<int> width(static_cast<std::size_t>(b.size()), -1);
  std::array<std::vector<int>, kEnds + 1> stacks;
  width[static_cast<std::size_t>(from)] = kEnds;
  stacks[kEnds].push_back(from);
  for (int top = kEnds; top >= 0;) {
    if (stacks[static_cast<std::size_t>(top)].empty()) {
      --top;
      continue;
    }
    const int w = top;
    const int i = stacks[static_cast<std::size_t>(top)].back();
    stacks[static_cast<std::size_t>(top)].pop_back();
    if (i == to)
      return w == kEnds ? std::numeric_limits<double>::infinity() : b.level_clearance(w);
    if (w < width[static_cast<std::size_t>(i)])
      continue;
    b.for_neighbours(i, [&](int n) {
      if (n != to && !b.open(n))
        return;
      const int c = n == to ? w : std::min(w, b.level(n));
      if (c > width[static_cast<std::size_t>(n)]) {
        width[static_cast<std::size_t>(n)] = c;
        stacks[static_cast<std::size_t>(c)].push_back(n);
      }
    });
  }
  return -std::numeric_limits<double>::infinity();
}

/// Step 3: the cheapest route from `from` to `to` through blocks at least `least` open. A* (Hart,
/// Nilsson & Raphael 1968): a move costs at least twice its length (c <= open_width), so twice
/// the straight distance to `to` never overestimates what is left, and no move lowers it by
/// more than its own cost; the first time a block leaves the queue, its cost is the least, as
/// with Dijkstra's search, which opens every block cheaper than the route.
std::vector<int> route(const GuideBlocks& b, int from, int to, double least, double open_width) {
  constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<double> cost(static_cast<std::size_t>(b.size()), kFar);
  std::vector<int> parent(static_cast<std::size_t>(b.size()), -1);
  std::vector<bool> done(static_cast<std::size_t>(b.size()), false);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;  // least estimate first
  const Eigen::Vector3d& end = b.centre(to);
  const auto left = [&](int n) { return 2.0 * (b.centre(n) - end).norm(); };
  cost[static_cast<std::size_t>(from)] = 0.0;
  queue.push({left(from), from});
  const double floor = 1e-3 * open_width;
  while (!queue.empty()) {
    const int i = queue.top().second;
    queue.pop();
    if (i == to)
      break;
    if (done[static_cast<std::size_t>(i)])
      continue;
    done[static_cast<std::size_t>(i)] = true;
    const double g = cost[static_cast<std::size_t>(i)];
    const Eigen::Vector3d& p = b.centre(i);
    const double ci = b.clearance(i);
    b.for_neighbours(i, [&](int n) {
      const double cn = b.clearance(n);
      if (n != to && (!b.open(n) || cn < least))
        return;
      const double c = std::clamp(std::min(cn, ci), floor, open_width);
      const double step = (b.centre(n) - p).norm() * (1.0 + open_width / c);
      if (g + step < cost[static_cast<std::size_t>(n)]) {
        cost[static_cast<std::size_t>(n)] = g + step;
        parent[static_cast<std::size_t>(n)] = i;
        queue.push({g + step + left(n), n});
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

#include "tandem/collision/distance_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tandem {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Felzenszwalb and Huttenlocher's 1-D transform: d[q] = min_p (q - p)^2 + f[p] over the finite
/// f[p] (the lower envelope of the parabolas rooted at them); infinite where no f[p] is finite.
/// v and z are scratch of sizes n and n + 1.
void transform_row(const double* f, int n, double* d, int* v, double* z) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (!std::isfinite(f[q]))
      continue;
    const double fq = f[q] + static_cast<double>(q) * q;
    double s = -kInfinity;
    while (k >= 0) {
      const int p = v[k];
      s = (fq - (f[p] + static_cast<double>(p) * p)) / (2.0 * (q - p));
      if (s > z[k])
        break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -kInfinity : s;
    z[k + 1] = kInfinity;
  }
  if (k < 0) {
    std::fill(d, d + n, kInfinity);
    return;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q)
      ++k;
    const double dq = q - v[k];
    d[q] = dq * dq + f[v[k]];
  }
}

/// x in whole quanta, rounded down, at most 255.
std::uint8_t quanta(double x) {
  return static_cast<std::uint8_t>(std::min(255.0, std::floor(x)));
}

}  // namespace

DistanceGrid::DistanceGrid(const Box& region, double spacing,
                           const std::vector<Triangle>& triangles, const std::vector<Box>& solids,
                           std::size_t max_cells) {
  const Eigen::Vector3d size = (region.max - region.min).cwiseMax(0.0);
  for (;;) {
    dims_ = ((size / spacing).array().ceil() + 2.0).cast<int>();
    const double cells = static_cast<double>(dims_.x()) * dims_.y() * dims_.z();
    if (cells <= static_cast<double>(max_cells))
      break;
    spacing *= std::cbrt(cells / static_cast<double>(max_cells)) * 1.01;
  }
  spacing_ = spacing;
  inverse_spacing_ = 1.0 / spacing;
  origin_ = region.min - Eigen::Vector3d::Constant(spacing);
  // The rounding of the cell index and of the centre is far below this margin.
  slack_ = spacing * (0.5 * std::sqrt(3.0) + 1e-6);
  quantum_ = spacing / 8.0;
  distance_.assign(static_cast<std::size_t>(dims_.prod()), 255);
  for (const Triangle& t : triangles)
    mark_triangle(t, 0);
  for (const Box& b : solids)
    mark_box(b.min, b.max);
  transform();
}

Eigen::Vector3i DistanceGrid::cell_of(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d u = ((p - origin_) * inverse_spacing_).array().floor();
  const Eigen::Vector3d top = (dims_.array() - 1).cast<double>();
  return u.cwiseMax(0.0).cwiseMin(top).cast<int>();
}

void DistanceGrid::mark_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  // Clamping the cell range clamps the box onto the grid (see the header).
  const Eigen::Vector3i a = cell_of(lo);
  const Eigen::Vector3i b = cell_of(hi);
  for (int z = a.z(); z <= b.z(); ++z) {
    for (int y = a.y(); y <= b.y(); ++y) {
      for (int x = a.x(); x <= b.x(); ++x) {
        std::uint8_t& cell = distance_[index({x, y, z})];
        marked_ += cell != 0 ? 1 : 0;
        cell = 0;
      }
    }
  }
}

void DistanceGrid::mark_triangle(const Triangle& t, int depth) {
  const Eigen::Vector3d lo = t.a.cwiseMin(t.b).cwiseMin(t.c);
  const Eigen::Vector3d hi = t.a.cwiseMax(t.b).cwiseMax(t.c);
  // Depth 40 halves a side 2^20 times: far below any cell, and a bound on bad input.
  if ((hi - lo).maxCoeff() <= spacing_ || depth >= 40) {
    mark_box(lo, hi);
    return;
  }
  for (const Triangle& half : split_at_longest_edge(t))
    mark_triangle(half, depth + 1);
}

std::array<DistanceGrid::Triangle, 2> DistanceGrid::split_at_longest_edge(const Triangle& t) {
  const double ab = (t.b - t.a).squaredNorm(), bc = (t.c - t.b).squaredNorm(),
               ca = (t.a - t.c).squaredNorm();
  if (ab >= bc && ab >= ca) {
    const Eigen::Vector3d m = 0.5 * (t.a + t.b);
    return {Triangle{t.a, m, t.c}, Triangle{m, t.b, t.c}};
  }
  if (bc >= ca) {
    const Eigen::Vector3d m = 0.5 * (t.b + t.c);
    return {Triangle{t.a, t.b, m}, Triangle{t.a, m, t.c}};
  }
  const Eigen::Vector3d m = 0.5 * (t.c + t.a);
  return {Triangle{t.a, t.b, m}, Triangle{m, t.b, t.c}};
}

void DistanceGrid::transform() {
  // Squared distances in cells, one axis after the other (the transform is separable).
  const auto n_max = static_cast<std::size_t>(dims_.maxCoeff());
  std::vector<double> f, d;
  std::vector<int> v(n_max);
  std::vector<double> z(n_max + 1);
  const std::array<Eigen::Vector3i, 3> steps = {Eigen::Vector3i(1, 0, 0), Eigen::Vector3i(0, 1, 0),
                                                Eigen::Vector3i(0, 0, 1)};
  // Marked cells are 0, the others infinite, as squared distances.
  std::vector<double> squared(distance_.size(), kInfinity);
  for (std::size_t i = 0; i < squared.size(); ++i) {
    if (distance_[i] == 0)
      squared[i] = 0.0;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int n = dims_[axis];
    f.resize(static_cast<std::size_t>(n));
    d.resize(static_cast<std::size_t>(n));
    Eigen::Vector3i other = dims_;
    other[axis] = 1;
    const Eigen::Vector3i step = steps[static_cast<std::size_t>(axis)];
    for (int c = 0; c < other.z(); ++c) {
      for (int b = 0; b < other.y(); ++b) {
        for (int a = 0; a < other.x(); ++a) {
          const Eigen::Vector3i start(a, b, c);
          for (int q = 0; q < n; ++q)
            f.data()[q] = squared[index(start + q * step)];
          transform_row(f.data(), n, d.data(), v.data(), z.data());
          for (int q = 0; q < n; ++q)
            squared[index(start + q * step)] = d.data()[q];
        }
      }
    }
  }
  for (std::size_t i = 0; i < squared.size(); ++i)
    distance_[i] = quanta(std::sqrt(squared[i]) * 8.0);
}

}  // namespace tandem

#include "tandem/collision/sphere_tree.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace tandem {
namespace {

using Ball = SphereTree::Ball;

Ball triangle_ball(const DistanceGrid::Triangle& t) {
  const Eigen::Vector3d lo = t.a.cwiseMin(t.b).cwiseMin(t.c);
  const Eigen::Vector3d hi = t.a.cwiseMax(t.b).cwiseMax(t.c);
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double r = std::max({(t.a - centre).norm(), (t.b - centre).norm(), (t.c - centre).norm()});
  return {centre, r};
}

/// Splits the triangle at its longest edge until its ball fits the radius.
void split_triangle(const DistanceGrid::Triangle& t, double radius, int depth,
                    std::vector<Ball>& out) {
  const Ball ball = triangle_ball(t);
  if (ball.radius <= radius || depth >= 30) {
    out.push_back(ball);
    return;
  }
  for (const DistanceGrid::Triangle& half : DistanceGrid::split_at_longest_edge(t))
    split_triangle(half, radius, depth + 1, out);
}

}  // namespace

SphereTree::SphereTree(const std::vector<DistanceGrid::Triangle>& triangles,
                       const std::vector<DistanceGrid::Box>& solids, double leaf_radius) {
  std::vector<Ball> balls;
  for (const DistanceGrid::Triangle& t : triangles)
    split_triangle(t, leaf_radius, 0, balls);
  for (const DistanceGrid::Box& b : solids)
    balls.push_back({0.5 * (b.min + b.max), 0.5 * (b.max - b.min).norm()});
  leaves_ = balls.size();
  if (!balls.empty()) {
    nodes_.reserve(2 * balls.size());
    build(balls, 0, balls.size());
  }
}

int SphereTree::build(std::vector<Ball>& balls, std::size_t begin, std::size_t end) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  Eigen::Vector3d centres_lo = lo, centres_hi = hi;
  for (std::size_t i = begin; i < end; ++i) {
    const Ball& b = balls[i];
    lo = lo.cwiseMin(b.centre - Eigen::Vector3d::Constant(b.radius));
    hi = hi.cwiseMax(b.centre + Eigen::Vector3d::Constant(b.radius));
    centres_lo = centres_lo.cwiseMin(b.centre);
    centres_hi = centres_hi.cwiseMax(b.centre);
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  double radius = 0.0;
  for (std::size_t i = begin; i < end; ++i)
    radius = std::max(radius, (balls[i].centre - centre).norm() + balls[i].radius);
  const std::size_t id = nodes_.size();
  nodes_.push_back({centre, radius, -1, -1});
  if (end - begin == 1) {
    nodes_[id].centre = balls[begin].centre;
    nodes_[id].radius = balls[begin].radius;
    return static_cast<int>(id);
  }
  // Median split along the longest side of the centres' box.
  int axis = 0;
  (centres_hi - centres_lo).maxCoeff(&axis);
  const std::size_t mid = begin + (end - begin) / 2;
  std::nth_element(
      balls.begin() + static_cast<std::ptrdiff_t>(begin),
      balls.begin() + static_cast<std::ptrdiff_t>(mid),
      balls.begin() + static_cast<std::ptrdiff_t>(end),
      [axis](const Ball& a, const Ball& b) { return a.centre[axis] < b.centre[axis]; });
  const int first = build(balls, begin, mid);
  const int second = build(balls, mid, end);
  nodes_[id].first_child = first;
  nodes_[id].second_child = second;
  return static_cast<int>(id);
}

double SphereTree::clearance_at(const DistanceGrid& grid, const Eigen::Isometry3d& X_WO,
                                double enough, double enough_for_all, int budget,
                                std::uint64_t* opened) const {
  if (nodes_.empty())
    return enough_for_all;
  const int given = budget;
  const auto done = [&](double bound) {
    if (opened != nullptr)
      *opened += static_cast<std::uint64_t>(given - std::max(budget, 0));
    return bound;
  };
  auto bound_of = [&](const Node& n) { return grid.lower_bound(X_WO * n.centre) - n.radius; };
  double best = enough_for_all;
  // Depth first, the child with the lower bound first: a configuration the grid cannot certify
  // shows it at the first leaf below `enough`, which lies under the lowest bounds.
  std::array<std::pair<std::size_t, double>, 128> stack{};
  std::size_t top = 0;
  stack[top++] = {0, bound_of(nodes_[0])};
  while (top > 0) {
    const auto [id, bound] = stack[--top];
    if (bound >= best)
      continue;  // every leaf below is at least this far: no lower minimum there
    const Node& n = nodes_[id];
    if (n.first_child < 0) {
      best = bound;
      if (best < enough)
        return done(best);
      continue;
    }
    if (--budget < 0 || top + 2 > stack.size())
      return done(-1.0);  // too dear to settle here: FCL decides
    const auto a = static_cast<std::size_t>(n.first_child);
    const auto b = static_cast<std::size_t>(n.second_child);
    const double bound_a = bound_of(nodes_[a]), bound_b = bound_of(nodes_[b]);
    if (bound_a < bound_b) {
      stack[top++] = {b, bound_b};
      stack[top++] = {a, bound_a};
    } else {
      stack[top++] = {a, bound_a};
      stack[top++] = {b, bound_b};
    }
  }
  return done(best);
}

}  // namespace tandem

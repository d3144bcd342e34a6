#include "tandem/planning/path.hpp"

#include <algorithm>
#include <cmath>

namespace tandem {

double path_length(const SE3Space& space, const Path& path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += space.distance(path[i - 1], path[i]);
  return length;
}

std::string PathCheck::describe() const {
  if (valid)
    return "valid";
  if (motion) {
    return "the motion from state " + std::to_string(index - 1) + " to state " +
           std::to_string(index) + " collides";
  }
  return "state " + std::to_string(index) +
         (out_of_bounds ? " is outside the bounds" : " is in collision");
}

PathCheck check_path(const Path& path, MotionValidator& validator) {
  PathCheck r;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!validator.space().satisfies_bounds(path[i])) {
      return PathCheck{false, i, false, true};
    }
    if (!validator.is_valid(path[i]))
      return PathCheck{false, i, false, false};
    if (i > 0 && !validator.check_motion(path[i - 1], path[i]))
      return PathCheck{false, i, true, false};
  }
  return r;
}

namespace {

std::size_t attempts(const Path& path, const SimplifyOptions& options) {
  return static_cast<std::size_t>(
      std::ceil(options.attempts_per_state * static_cast<double>(path.size())));
}

/// Removes runs of vertices that a direct motion can bypass.
void reduce_vertices(Path& path, MotionValidator& validator, Rng& rng,
                     const SimplifyOptions& options) {
  const std::size_t max_steps = attempts(path, options);
  const std::size_t max_empty = std::max<std::size_t>(path.size() / 2, 4);
  std::size_t empty = 0;
  for (std::size_t s = 0; s < max_steps && empty < max_empty && path.size() > 2; ++s) {
    const std::size_t n = path.size();
    std::size_t a = rng.below(n);
    std::size_t b = rng.below(n);
    if (a > b)
      std::swap(a, b);
    if (b - a < 2) {
      ++empty;
      continue;
    }
    if (validator.check_motion(path[a], path[b])) {
      path.erase(path.begin() + static_cast<std::ptrdiff_t>(a + 1),
                 path.begin() + static_cast<std::ptrdiff_t>(b));
      empty = 0;
    } else {
      ++empty;
    }
  }
}

/// Joins random points on two non-adjacent segments when that is valid and shorter.
void shortcut(Path& path, MotionValidator& validator, Rng& rng, const SimplifyOptions& options) {
  const SE3Space& space = validator.space();
  const std::size_t max_steps = attempts(path, options);
  for (std::size_t s = 0; s < max_steps && path.size() > 2; ++s) {
    const std::size_t segments = path.size() - 1;
    std::size_t i = rng.below(segments);
    std::size_t j = rng.below(segments);
    if (i > j)
      std::swap(i, j);
    if (j - i < 1)
      continue;
    const double ti = rng.uniform01();
    const double tj = rng.uniform01();
    const Config qa = space.interpolate(path[i], path[i + 1], ti);
    const Config qb = space.interpolate(path[j], path[j + 1], tj);
    double old_length = space.distance(qa, path[i + 1]) + space.distance(path[j], qb);
    for (std::size_t k = i + 1; k < j; ++k)
      old_length += space.distance(path[k], path[k + 1]);
    const double new_length = space.distance(qa, qb);
    if (!(new_length < old_length - 1e-12 * std::max(1.0, old_length)))
      continue;
    // The pieces qa -> path[i+1] and path[j] -> qb are not motions of the path anymore; the new
    // motions path[i] -> qa, qa -> qb and qb -> path[j+1] must each be checked at their own
    // resolution.
    if (!validator.is_valid(qa) || !validator.is_valid(qb))
      continue;
    if (!validator.check_motion(path[i], qa) || !validator.check_motion(qa, qb) ||
        !validator.check_motion(qb, path[j + 1])) {
      continue;
    }
    Path next(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i + 1));
    next.push_back(qa);
    next.push_back(qb);
    next.insert(next.end(), path.begin() + static_cast<std::ptrdiff_t>(j + 1), path.end());
    path = std::move(next);
  }
}

}  // namespace

Path simplify_path(Path path, MotionValidator& validator, Rng& rng,
                   const SimplifyOptions& options) {
  if (path.size() > 2 && validator.check_motion(path.front(), path.back()))
    return {path.front(), path.back()};
  double length = path_length(validator.space(), path);
  for (int round = 0; round < options.max_rounds; ++round) {
    reduce_vertices(path, validator, rng, options);
    shortcut(path, validator, rng, options);
    // Drop repeated states (a shortcut may start exactly at a vertex).
    path.erase(std::unique(path.begin(), path.end()), path.end());
    const double shorter = path_length(validator.space(), path);
    const bool converged = shorter > (1.0 - options.min_gain) * length;
    length = shorter;
    if (converged)
      break;
  }
  return path;
}

Path cut_at_goal_region(const Path& path, const GoalRegion& region, const SE3Space& space) {
  std::size_t first = 0;
  while (first < path.size() && !region.contains(path[first]))
    ++first;
  if (first == path.size() || first == 0)
    return path;
  Path cut(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(first));
  const Config& a = path[first - 1];
  const Config& b = path[first];
  double outside = 0.0, inside = 1.0;
  for (int k = 0; k < 40; ++k) {
    const double mid = (outside + inside) / 2.0;
    (region.contains(space.interpolate(a, b, mid)) ? inside : outside) = mid;
  }
  cut.push_back(space.interpolate(a, b, inside));
  return cut;
}

}  // namespace tandem

#pragma once
// Paths: sequences of configurations, joined by the space's geodesic motions.

#include <cstddef>
#include <string>
#include <vector>

#include "tandem/collision/motion_validator.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/scene/goal_region.hpp"

namespace tandem {

using Path = std::vector<Config>;

/// Sum of the metric distances between consecutive configurations.
double path_length(const SE3Space& space, const Path& path);

struct PathCheck {
  bool valid = true;
  std::size_t index = 0;  ///< first invalid state, or the end state of the first invalid motion
  bool motion = false;    ///< true if the state is valid but the motion into it is not
  bool out_of_bounds = false;
  std::string describe() const;
};

/// Checks every state (bounds and collision) and every motion between consecutive states at the
/// space's resolution, in order; stops at the first fault.
PathCheck check_path(const Path& path, MotionValidator& validator);

struct SimplifyOptions {
  /// Attempts of each pass, as a multiple of the path's size (OMPL's simplifier uses the size
  /// itself).
  double attempts_per_state = 2.0;
  /// Rounds of both passes at most; a round that shortens the path by less than min_gain ends it.
  int max_rounds = 8;
  double min_gain = 0.01;
};

/// Shortens a valid path (the start and the goal stay): tries the direct motion, removes vertices
/// that can be bypassed (OMPL's reduceVertices), then joins random points on non-adjacent segments
/// (shortcutPath). Every new
/// motion is validated; the result is valid and never longer. Deterministic for a given rng state.
Path simplify_path(Path path, MotionValidator& validator, Rng& rng,
                   const SimplifyOptions& options = {});

/// The path up to where it first enters the goal region: the states before the first state in
/// the region, then the point where the motion into that state enters the region (to 2^-40 of
/// the motion, by bisection; a point of a valid motion, so the path stays valid). A path that
/// never enters the region is returned whole.
Path cut_at_goal_region(const Path& path, const GoalRegion& region, const SE3Space& space);

}  // namespace tandem

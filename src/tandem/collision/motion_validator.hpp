#pragma once
// Validity of configurations (inside the bounds and collision-free) and of motions between them,
// checked at the space's resolution.
//
// A motion from a to b is checked at the configurations space.step(a, b, k, n), k = 1..n, with
// n = space.segment_count(a, b). step() is symmetric, so a motion checked in either direction
// visits the same configurations, and `tandem check-path` re-checks exactly what the planner
// checked.
//
// Threading: not thread-safe (it drives one CollisionChecker); one per thread.

#include <cstdint>
#include <vector>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

struct MotionCheck {
  bool valid = false;  ///< every configuration of the motion is valid
  /// The last valid configuration reached going from a toward b (a itself if the first step
  /// collides), as the k-th of n steps.
  Config last_valid;
  unsigned last_valid_step = 0;
  unsigned steps = 0;
};

class MotionValidator {
 public:
  MotionValidator(const SE3Space& space, CollisionChecker& checker)
      : space_(space), checker_(checker) {}

  const SE3Space& space() const { return space_; }
  CollisionChecker& checker() { return checker_; }

  /// Inside the bounds and collision-free.
  bool is_valid(const Config& q) {
    ++checks_;
    if (!space_.satisfies_bounds(q))
      return false;
    if (!profiling_)
      return checker_.is_collision_free(q);
    const Stopwatch watch;
    const bool free = checker_.is_collision_free(q);
    check_seconds_ += watch.seconds();
    return free;
  }

  /// Measures the time spent in collision queries (two clock reads per query; off by default).
  void set_profiling(bool on) { profiling_ = on; }
  bool profiling() const { return profiling_; }
  /// Seconds spent in collision queries while profiling.
  double check_seconds() const { return check_seconds_; }

  /// Whether the motion a -> b is valid, assuming a is. Checks b first, then the intermediate
  /// configurations by bisection (midpoint first), which finds a collision sooner on average than a
  /// sweep; the same order as OMPL's DiscreteMotionValidator.
  bool check_motion(const Config& a, const Config& b);

  /// Sweeps from a toward b and reports the last valid configuration (the papers' Add_Tree
  /// extension), assuming a is valid.
  MotionCheck check_motion_last_valid(const Config& a, const Config& b);

  /// Number of configuration checks so far (each is one bounds test plus one collision query).
  std::uint64_t checks() const { return checks_; }

 private:
  const SE3Space& space_;
  CollisionChecker& checker_;
  std::uint64_t checks_ = 0;
  bool profiling_ = false;
  double check_seconds_ = 0.0;
  std::vector<std::pair<unsigned, unsigned>>
      queue_;  // reused by check_motion, no allocation per call
};

}  // namespace tandem

#pragma once
// Validity of configurations (inside the bounds and collision-free) and of motions between them.
//
// Two ways to check a motion (MotionValidation):
// - exact: the whole continuous motion a -> b is certified collision-free, as in
//   Schwarzer, Saha and Latombe, "Adaptive dynamic collision checking for single and multiple
//   articulated robots in complex environments" (IEEE TRO 2005) and hpp-core's continuous
//   validation. The motion translates by dt and turns by an angle theta about a fixed axis
//   (slerp), both at constant speed, so between fractions s and s' no point of the object moves
//   more than L |s - s'|, L = |dt| + theta * R (R: CollisionChecker::object_radius()). A
//   configuration at s whose clearance is at least c is therefore the centre of a collision-free
//   stretch of half-width c / L; the validator bisects the motion, each clearance bound
//   (CollisionChecker::clearance_bound) certifying a stretch, until the stretches cover [0, 1].
//   A configuration closer to an obstacle than the tolerance counts as contact: invalid. So a
//   valid configuration has a clearance of at least the tolerance, and every configuration of a
//   valid motion is collision-free.
// - discrete (the default for now; OMPL's DiscreteMotionValidator): the motion is checked at the
//   configurations space.step(a, b, k, n), k = 1..n, with n = space.segment_count(a, b) (1% of
//   the bounds' diagonal and of pi by default); it can step over an obstacle thinner than a step.
//   step() is symmetric, so a motion checked in either direction visits the same
//   configurations, and `tandem check-path --validation discrete` re-checks exactly what the
//   planner checked.
//
// With a helper thread (use_helper_thread), an exact check asks for a motion's states in rounds
// of independent queries that two threads answer together (query_helper.hpp): the end alone, the
// other coarse states, the ends' and the middle's clearances, then each level of the bisection.
// A round is answered whole even when one of its states fails, so the queries made, and their
// work, depend only on the motion, not on which thread answered what; the answer is the same as
// without the helper.
//
// Threading: not thread-safe (it drives one CollisionChecker, and its helper's); one per thread.

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "tandem/collision/clearance_cache.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validation.hpp"
#include "tandem/collision/query_helper.hpp"
#include "tandem/core/stopwatch.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

struct ValidationSettings {
  MotionValidation mode = MotionValidation::exact;
  /// Closer than this to an obstacle counts as contact (exact mode); 0: 1e-6 x the bounds'
  /// diagonal.
  double tolerance = 0.0;
  /// The checker's distance-grid pre-filter (CollisionChecker::use_distance_grid), built with
  /// cells of half a resolution step; off: FCL alone. The grid belongs to the checker, so
  /// validators that share a checker share it too.
  bool distance_grid = true;
  /// Exact mode: every configuration of a valid motion is at least this far from every obstacle
  /// (and the tolerance more). Every clearance bound is taken less this margin, so the
  /// certification above holds for the obstacles grown by it.
  double clearance = 0.0;
};

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
  MotionValidator(const SE3Space& space, CollisionChecker& checker,
                  const ValidationSettings& settings = {});

  const SE3Space& space() const { return space_; }
  CollisionChecker& checker() { return checker_; }

  /// Sets the way motions are checked (a planner sets its own settings' way when constructed).
  void configure(const ValidationSettings& settings);
  /// From now on, exact checks of motions ask in rounds (without a clearance margin; the header
  /// says how) shared with a thread of its own, which queries a clone of the checker.
  void use_helper_thread();
  /// Ends the helper thread, and the rounds: checks ask one query at a time again.
  void release_helper_thread() { helper_.reset(); }
  bool has_helper_thread() const { return helper_ != nullptr; }
  MotionValidation mode() const { return mode_; }
  /// The contact tolerance in scene units (exact mode).
  double tolerance() const { return tolerance_; }

  /// Inside the bounds and collision-free; in exact mode also at least the tolerance from every
  /// obstacle.
  bool is_valid(const Config& q) {
    if (!space_.satisfies_bounds(q)) {
      ++checks_;
      return false;
    }
    return mode_ == MotionValidation::exact ? clearance(q, tolerance_) >= tolerance_
                                            : collision_free(q);
  }

  /// Measures the time spent in collision queries (two clock reads per query; off by default).
  void set_profiling(bool on) { profiling_ = on; }
  bool profiling() const { return profiling_; }
  /// Seconds spent in collision queries while profiling.
  double check_seconds() const { return check_seconds_; }

  /// Whether the motion a -> b is valid, assuming a is. Checks b first, then the rest by bisection
  /// (midpoint first), which finds a collision sooner on average than a sweep; the same order as
  /// OMPL's DiscreteMotionValidator.
  bool check_motion(const Config& a, const Config& b) {
    return mode_ == MotionValidation::exact ? check_motion_exact(a, b)
                                            : check_motion_discrete(a, b);
  }

  /// Sweeps from a toward b and reports the last valid configuration (the papers' Add_Tree
  /// extension), assuming a is valid. In exact mode the sweep advances by certified stretches and
  /// stops in front of an obstacle: the last valid configuration is the last one whose clearance
  /// bound reached a tenth of a resolution step (and the tolerance);
  /// last_valid_step counts the discrete steps (of segment_count) it lies beyond a, so that a
  /// blocked extension adds a node only if it got at least one step away, in both modes.
  MotionCheck check_motion_last_valid(const Config& a, const Config& b) {
    return mode_ == MotionValidation::exact ? last_valid_exact(a, b) : last_valid_discrete(a, b);
  }

  /// Number of configuration checks so far (each is one bounds test plus one collision query, or
  /// in exact mode one clearance bound).
  std::uint64_t checks() const { return checks_; }
  /// The work of the checker's queries so far (query_work()).
  std::uint64_t work() const { return query_work(checker_.counters()); }

 private:
  /// Runs one query of the checker, counted in checks() and timed while profiling.
  template <class Query>
  auto counted(Query query);
  bool collision_free(const Config& q);
  /// checker_.clearance_bound(q, cap), FCL's cap limited to a quarter resolution step.
  double clearance(const Config& q, double cap);
  /// With a clearance margin: the bound beyond it (clearance(q, cap + margin) - margin), exact
  /// near the margin.
  double clearance_beyond_margin(const Config& q, double cap);
  /// L: no point of the object moves more than L |s - s'| between fractions s and s' of a -> b.
  double displacement_rate(const Config& a, const Config& b) const;
  bool check_motion_discrete(const Config& a, const Config& b);
  /// Whether b or one of a few of the motion's steps from a to b (kCoarseStates of them at most,
  /// in bisection order) collides: yes/no queries; false says nothing of the rest of the motion.
  bool collides_coarsely(const Config& a, const Config& b);
  bool check_motion_exact(const Config& a, const Config& b);
  /// check_motion_exact's steps in rounds shared with the helper thread.
  bool check_motion_in_rounds(const Config& a, const Config& b);
  /// The caps clearance(q, cap) asks of the checker: {cap, FCL's cap}.
  std::pair<double, double> clearance_caps(double cap) const;
  /// A round's clearance query of q, capped as clearance(q, cap) caps it.
  RoundQuery clearance_query(const Config& q, double cap) const;
  /// Answers round_ into answers_: clearances from the cache where it knows them, the rest (each
  /// counted in checks(), the clearances then cached in the round's order) on both threads.
  void answer_round();
  MotionCheck last_valid_discrete(const Config& a, const Config& b);
  MotionCheck last_valid_exact(const Config& a, const Config& b);

  const SE3Space& space_;
  CollisionChecker& checker_;
  MotionValidation mode_ = MotionValidation::exact;
  double tolerance_ = 0.0;
  double margin_ = 0.0;  ///< ValidationSettings::clearance
  std::uint64_t checks_ = 0;
  bool profiling_ = false;
  double check_seconds_ = 0.0;
  // Reused by check_motion, no allocation per call.
  std::vector<std::pair<unsigned, unsigned>> queue_;
  std::vector<std::pair<double, double>> stretches_;
  ClearanceCache cache_;
  std::unique_ptr<QueryHelper> helper_;
  // Reused by check_motion_in_rounds: the round, its answers, and the queries the cache did not
  // answer (with their indices in the round) and their replies.
  std::vector<RoundQuery> round_;
  std::vector<double> answers_;
  std::vector<RoundQuery> asked_;
  std::vector<std::size_t> asked_index_;
  std::vector<double> replies_;
};

}  // namespace tandem

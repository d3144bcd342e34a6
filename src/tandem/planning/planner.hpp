#pragma once
// The planner interface: steppable, interruptible, deterministic for a given seed.
//
// A planner is driven either by solve() (until solved, a time or iteration limit, or interrupt()),
// or one iteration at a time by step() — the interactive loop and the viewer drive it that way (the
// startSolve / oneStep / interrupt pattern of hpp-core). Outcomes are values (PlannerStatus), not
// exceptions.
//
// Threading: step() and solve() run on one thread (the planner thread). interrupt() may be called
// from any thread. stats(), trees() and solution() may be read on the planner thread, or by others
// only while the planner is not stepping.

#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tandem/collision/motion_validator.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/planning/extend_status.hpp"
#include "tandem/planning/planner_settings.hpp"
#include "tandem/planning/tree.hpp"
#include "tandem/sampling/target_sampler.hpp"

namespace tandem {

enum class PlannerStatus : std::uint8_t {
  running,          ///< not solved yet; step() may be called again
  solved,           ///< solution() holds a valid path from start to goal
  timeout,          ///< solve() reached its time limit
  iteration_limit,  ///< solve() reached its iteration limit
  interrupted,      ///< interrupt() was called
  invalid_start,    ///< the start is outside the bounds or in collision
  invalid_goal,     ///< the goal is outside the bounds or in collision
};

std::string_view to_string(PlannerStatus status);

struct PlannerStats {
  double time_s = 0.0;                 ///< wall time spent in solve()
  std::uint64_t iterations = 0;        ///< step() calls that sampled
  std::size_t nodes = 0;               ///< in all trees, roots included
  std::size_t edges = 0;               ///< nodes minus roots
  std::uint64_t collision_checks = 0;  ///< configuration checks by this planner's validator
  /// The work of its validator's collision queries (query_work(): tests of boxes and triangles,
  /// weighted), the same on every machine; the portfolio's race is run on it.
  std::uint64_t work = 0;
  /// Time in collision queries and in nearest-neighbour queries (with settings.profile).
  double collision_time_s = 0.0;
  double nearest_time_s = 0.0;
  /// Nodes per NodeSource (root, random, operator, contact).
  std::array<std::size_t, kNodeSources> nodes_by_source{};
  /// Time the planner thread spent computing operator states (virtual-time feeds).
  double operator_time_s = 0.0;
  /// Iterations in which the operator had authority, and how often contact mode was entered.
  std::uint64_t operator_iterations = 0;
  std::uint64_t contact_entries = 0;
  /// Authority sharing's alpha in the latest iteration (automatic alpha moves it); NaN without.
  double alpha = std::numeric_limits<double>::quiet_NaN();
  /// Outcomes of the extensions toward the iterations' targets (connections not included), the
  /// I-RRT's classes: Collision (nothing added), Reached, Obstacle (stopped short of the target).
  std::uint64_t extensions_collision = 0;
  std::uint64_t extensions_reached = 0;
  std::uint64_t extensions_obstacle = 0;
};

struct Termination {
  double time_limit_s = std::numeric_limits<double>::infinity();
  std::uint64_t max_iterations = std::numeric_limits<std::uint64_t>::max();
  /// When set, solve() returns interrupted at the first iteration that finds it true (a flag
  /// shared by several planners, e.g. an experiment's workers stopped by Ctrl-C).
  const std::atomic<bool>* stop = nullptr;
};

/// Base of the tree planners: the step / solve / interrupt cycle, statistics, the start and goal
/// checks. It knows nothing of operators: interactive planners take a TargetSampler (RRT,
/// RRT-Connect) or an Interaction (the I-RRT) of their own.
class Planner : public RoadmapView {
 public:
  Planner(MotionValidator& validator, const Config& start, const Config& goal,
          const PlannerSettings& settings);
  virtual ~Planner() = default;
  Planner(const Planner&) = delete;
  Planner& operator=(const Planner&) = delete;

  /// The algorithm ("rrt-connect", "rrt", "irrt"); the registry name says how it was set up.
  virtual std::string_view name() const = 0;

  /// One iteration. The first call checks the start and the goal. Returns running until solved;
  /// after a terminal status, returns it again without doing anything.
  PlannerStatus step();

  /// Steps until solved, interrupted, or a limit is reached.
  PlannerStatus solve(const Termination& termination);

  /// Asks solve() to return at its next iteration. Thread-safe.
  void interrupt() { interrupt_requested_.store(true, std::memory_order_relaxed); }

  PlannerStatus status() const { return status_; }
  const PlannerStats& stats() const { return stats_; }
  const std::vector<Config>& solution() const { return solution_; }
  const PlannerSettings& settings() const { return settings_; }
  double range() const { return range_; }
  /// The trees, for display and statistics; the first is rooted at the start.
  virtual std::vector<const Tree*> trees() const = 0;
  /// A value per node that a viewer may colour by (the I-RRT's distance-to-goal label), in scene
  /// units; nothing for planners without one.
  virtual std::optional<double> node_label(std::size_t tree, NodeId node) const {
    (void)tree;
    (void)node;
    return std::nullopt;
  }
  /// Metric distance from q to the nearest node of the tree rooted at the start: the tree the
  /// operator carries toward the goal, which a watching operator keeps up with.
  double distance_to_roadmap(const Config& q) const override;

 protected:
  /// One iteration of the algorithm; returns true when solution_ has been set.
  virtual bool iterate() = 0;

  void update_counts();
  /// Subclasses call this for each tree they own, after constructing it.
  void attach(Tree& tree);
  /// Counts an extension toward an iteration's target in the statistics.
  void count_extension(ExtendStatus status);
  /// The collision queries this search has made so far.
  std::uint64_t queries_so_far() const { return validator_.checks() - checks_at_start_; }
  /// What a variant counts of its own (a sampler's operator counters); called by update_counts().
  virtual SamplerStats sampler_stats() const { return {}; }

  MotionValidator& validator_;
  const SE3Space& space_;
  Config start_, goal_;
  PlannerSettings settings_;
  double range_;
  Rng rng_;
  std::vector<Config> solution_;

 private:
  PlannerStatus status_ = PlannerStatus::running;
  bool started_ = false;
  std::uint64_t checks_at_start_ = 0;
  std::uint64_t work_at_start_ = 0;
  double check_seconds_at_start_ = 0.0;
  double nearest_seconds_ = 0.0;
  PlannerStats stats_;
  std::atomic<bool> interrupt_requested_{false};
  std::array<std::uint64_t, 4> extension_outcomes_{};
};

}  // namespace tandem

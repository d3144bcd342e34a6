#pragma once
// The automatic planners' settings, declared once (planner_parameters()): the default member
// initialisers are the defaults, the table gives ranges, units, help and the planners that use
// each. The command line, problem files, experiments, the JSON output and the journal read them
// from here.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "tandem/collision/motion_validator.hpp"
#include "tandem/core/parameter.hpp"
#include "tandem/interaction/interaction_settings.hpp"

namespace tandem {

/// How a tree grows toward a target it cannot reach in one collision-free motion.
enum class ExtendMode : std::uint8_t {
  classic,     ///< Kuffner & LaValle 2000: the whole step is valid or nothing is added (OMPL's
               ///< RRTConnect)
  last_valid,  ///< the papers' Add_Tree: the last valid configuration along the motion is added
};

/// "classic" or "last-valid" (the names the command line and scenario files use).
std::string_view to_string(ExtendMode mode);
std::optional<ExtendMode> parse_extend_mode(std::string_view name);

struct PlannerSettings {
  /// Longest motion added in one extension; 0 means 0.2 x the space's maximum extent (OMPL).
  double range = 0.0;
  /// The computer-alone planners' adaptive step (planning/adaptive_step.hpp): the smallest step,
  /// as a share of range, a node's extensions shrink to at first (it falls as a search goes on
  /// without a path); 1: a fixed step of range (OMPL's).
  double adaptive_step = 0.125;
  /// RRT-Connect's share of iterations, after its first kPassageWarmup, that aim at passage
  /// islands (passage_islands.hpp); 0: none.
  double passages = 0.1;
  /// RRT-Connect's share of uniform samples drawn along a workspace guide
  /// (sampling/guided_sampler.hpp: from the first iteration where the part fits the route
  /// lengthwise, else after GuidedSampler::kGuideWarmup); 0: none.
  double guide = 0.75;
  /// RRT's and the I-RRT's probability of extending toward the goal, in [0, 1].
  double goal_bias = 0.05;
  /// The run's only source of randomness.
  std::uint64_t seed = 1;
  ExtendMode extend = ExtendMode::classic;
  /// "kdtree" or "linear".
  std::string nearest_neighbors = "kdtree";
  /// How motions are checked: the whole continuous motion (exact) or every 1% (discrete, OMPL's).
  MotionValidation validation = MotionValidation::exact;
  /// Closer than this to an obstacle counts as contact (exact validation); 0: 1e-6 x the bounds'
  /// diagonal.
  double tolerance = 0.0;
  /// Keep at least this far from every obstacle along every motion (exact validation; a path
  /// finder's clash accuracy); 0: only the contact tolerance.
  double clearance = 0.0;
  /// The distance-grid pre-filter of collision queries (ValidationSettings::distance_grid).
  bool distance_grid = true;
  /// Independent searches run at once by the planners that plan alone (runs/portfolio.hpp); 0:
  /// one per core.
  unsigned threads = 0;
  /// Measure the time spent in collision checks and nearest-neighbour queries.
  bool profile = false;
  /// The interactive planners' tunables (interaction_parameters()).
  InteractionSettings interaction;
};

/// How a planner with these settings checks motions (its validator is configured so).
inline ValidationSettings validation_settings(const PlannerSettings& s) {
  return {s.validation, s.tolerance, s.distance_grid, s.clearance};
}

/// The declarations of PlannerSettings' tunable fields (range, goal_bias, extend,
/// nearest_neighbors, validation, tolerance, clearance, distance_grid, threads); the seed is the
/// run's, not a tunable.
const ParamTable<PlannerSettings>& planner_parameters();

}  // namespace tandem

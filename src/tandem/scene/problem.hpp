#pragma once
// A motion planning problem: scene, configuration space, start, goal, and what the problem file
// says about planning (the command line may override each of these).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tandem/core/parameter.hpp"
#include "tandem/scene/goal_region.hpp"
#include "tandem/scene/scene.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

/// Planning settings a problem file may carry. Empty optionals mean "use tandem's default".
struct ProblemPlannerHints {
  std::optional<std::string> planner;   ///< a planner of the registry (checked when run)
  std::map<std::string, double> range;  ///< per planner name ("rrt", "birrt")
  std::optional<double> time_limit;     ///< seconds
  std::optional<std::uint64_t> seed;
  std::optional<std::uint32_t> run_count;  ///< benchmark runs ([benchmark] run_count in OMPL.app)
  /// Any other tunable the problem sets (by its declared name; checked when a run is made).
  struct Value {
    std::string name;
    ParamValue value;
    std::string where;  ///< file:line
  };
  std::vector<Value> values;
};

struct Problem {
  std::string name;
  std::string source;  ///< the file or built-in name it was loaded from
  Scene scene;
  SE3Space space;
  Config start;
  Config goal;
  ProblemPlannerHints hints;
  /// A simulated operator's guide: a few keyframes placed by hand, as a person would gesture the
  /// way (coarse; it may pass through obstacles). Empty if the problem has none.
  std::vector<Config> guide;
  /// "Take this part out": any configuration in the region is a goal; `goal` is one of them, the
  /// one the planners aim at, and a solution ends where it first enters the region.
  std::optional<GoalRegion> goal_region;
};

/// A guide has at most this many keyframes (so that it stays a gesture, not a path).
inline constexpr std::size_t kMaxGuideKeyframes = 12;

}  // namespace tandem

#include "tandem/planning/rrt.hpp"

#include "tandem/planning/extend.hpp"

namespace tandem {

RRT::RRT(MotionValidator& validator, const Config& start, const Config& goal,
         const PlannerSettings& settings)
    : Planner(validator, start, goal, settings),
      tree_(validator.space(), settings.nearest_neighbors, start) {
  attach(tree_);
}

bool RRT::iterate() {
  const bool toward_goal = rng_.uniform01() < settings_.goal_bias;
  const Config q_rand = toward_goal ? goal_ : space_.sample_uniform(rng_);
  const Extension ext = extend(tree_, q_rand, range_, validator_, settings_.extend);
  count_extension(ext.status);
  if (ext.status != ExtendStatus::reached || !toward_goal)
    return false;
  solution_ = tree_.path_from_root(ext.node);
  return true;
}

}  // namespace tandem

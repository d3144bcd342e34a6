#include "tandem/planning/rrt.hpp"

#include "tandem/planning/extend.hpp"

namespace tandem {

RRT::RRT(MotionValidator& validator, const Config& start, const Config& goal,
         const PlannerSettings& settings, std::unique_ptr<TargetSampler> sampler)
    : Planner(validator, start, goal, settings),
      tree_(validator.space(), settings.nearest_neighbors, start),
      steps_(range_, adaptive_floor(settings)),
      sampler_(sampler != nullptr ? std::move(sampler)
                                  : std::make_unique<UniformSampler>(validator.space())) {
  attach(tree_);
}

bool RRT::iterate() {
  steps_.relax(queries_so_far());
  // 1. The goal, or the sampler's targets.
  const bool toward_goal = rng_.uniform01() < settings_.goal_bias;
  targets_.clear();
  if (toward_goal)
    targets_.push_back({goal_, NodeSource::random});
  else
    sampler_->sample({stats().iterations, this, &rng_}, targets_);
  for (const Target& target : targets_) {
    // 2. EXTEND.
    const Extension ext =
        extend(tree_, target.q, range_, validator_, settings_.extend, target.source, &steps_);
    count_extension(ext.status);
    // 3. Solved when the goal is reached.
    if (toward_goal && ext.status == ExtendStatus::reached) {
      solution_ = tree_.path_from_root(ext.node);
      return true;
    }
  }
  return false;
}

}  // namespace tandem

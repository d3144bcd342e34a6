#pragma once
// RRT with goal bias:
//   S. M. LaValle, "Rapidly-exploring random trees: A new tool for path planning", TR 98-11, 1998.
//
// Each iteration:
//   1. q_rand <- the goal with probability goal_bias, else the sampler's targets (a uniform sample
//      without a sampler)
//   2. EXTEND(T, q_rand) for each target by q_near's adaptive step (adaptive_step.hpp)
//   3. solved when an extension toward the goal reaches it

#include <memory>

#include "tandem/planning/adaptive_step.hpp"
#include "tandem/planning/planner.hpp"

namespace tandem {

class RRT final : public Planner {
 public:
  /// Without a sampler, uniform samples.
  RRT(MotionValidator& validator, const Config& start, const Config& goal,
      const PlannerSettings& settings, std::unique_ptr<TargetSampler> sampler = nullptr);

  std::string_view name() const override { return "rrt"; }
  std::vector<const Tree*> trees() const override { return {&tree_}; }

 protected:
  bool iterate() override;
  SamplerStats sampler_stats() const override { return sampler_->stats(); }

 private:
  Tree tree_;
  AdaptiveStep steps_;  ///< adaptive_step.hpp
  std::unique_ptr<TargetSampler> sampler_;
  std::vector<Target> targets_;
};

}  // namespace tandem

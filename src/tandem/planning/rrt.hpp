#pragma once
// RRT with goal bias:
//   S. M. LaValle, "Rapidly-exploring random trees: A new tool for path planning", TR 98-11, 1998.
//
// Each iteration:
//   1. q_rand <- the goal with probability goal_bias, else a uniform sample.
//   2. EXTEND(T, q_rand).
//   3. Solved when the node added is the goal.

#include "tandem/planning/planner.hpp"

namespace tandem {

class RRT final : public Planner {
 public:
  RRT(MotionValidator& validator, const Config& start, const Config& goal,
      const PlannerSettings& settings);

  std::string_view name() const override { return "rrt"; }
  std::vector<const Tree*> trees() const override { return {&tree_}; }

 protected:
  bool iterate() override;

 private:
  Tree tree_;
};

}  // namespace tandem

#pragma once
// RRT-Connect, the bidirectional RRT ("BiRRT") of
//   J. J. Kuffner and S. M. LaValle, "RRT-Connect: An efficient approach to single-query path
//   planning", ICRA 2000.
//
// Each iteration:
//   1. q_rand <- uniform sample.
//   2. EXTEND(T_a, q_rand) -> q_new (unless TRAPPED).
//   3. CONNECT(T_b, q_new): EXTEND T_b toward q_new while it ADVANCES.
//   4. If T_b REACHED q_new, the trees meet: the path is start -> q_new -> goal.
//   5. Swap the roles of T_a and T_b.
// The tree to extend alternates between the start and the goal tree, as in OMPL's RRTConnect.

#include "tandem/planning/planner.hpp"

namespace tandem {

class RRTConnect final : public Planner {
 public:
  RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
             const PlannerSettings& settings);

  std::string_view name() const override { return "birrt"; }
  std::vector<const Tree*> trees() const override { return {&start_tree_, &goal_tree_}; }

 protected:
  bool iterate() override;

 private:
  Tree start_tree_;
  Tree goal_tree_;
  bool extend_start_tree_ = true;
};

}  // namespace tandem

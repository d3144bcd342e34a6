#include "tandem/planning/rrt_connect.hpp"

#include "tandem/planning/extend.hpp"

namespace tandem {

RRTConnect::RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
                       const PlannerSettings& settings)
    : Planner(validator, start, goal, settings),
      start_tree_(validator.space(), settings.nearest_neighbors, start),
      goal_tree_(validator.space(), settings.nearest_neighbors, goal) {
  attach(start_tree_);
  attach(goal_tree_);
}

bool RRTConnect::iterate() {
  Tree& tree_a = extend_start_tree_ ? start_tree_ : goal_tree_;
  Tree& tree_b = extend_start_tree_ ? goal_tree_ : start_tree_;
  const bool a_is_start = extend_start_tree_;
  extend_start_tree_ = !extend_start_tree_;

  // 1-2. Sample and extend.
  const Config q_rand = space_.sample_uniform(rng_);
  const Extension ext = extend(tree_a, q_rand, range_, validator_, settings_.extend);
  if (ext.status == ExtendStatus::trapped)
    return false;

  // 3. Connect the other tree to q_new.
  const Config q_new = tree_a.nodes[ext.node];
  Extension con;
  do {
    con = extend(tree_b, q_new, range_, validator_, settings_.extend);
  } while (con.status == ExtendStatus::advanced);
  if (con.status != ExtendStatus::reached)
    return false;

  // 4. The trees meet at q_new, present in both: keep it once.
  const NodeId start_node = a_is_start ? ext.node : con.node;
  const NodeId goal_node = a_is_start ? con.node : ext.node;
  solution_ = start_tree_.path_from_root(start_node);
  std::vector<Config> to_goal = goal_tree_.path_from_root(goal_node);
  solution_.insert(solution_.end(), to_goal.rbegin() + 1, to_goal.rend());
  return true;
}

}  // namespace tandem

#include "tandem/planning/rrt_connect.hpp"

#include "tandem/planning/extend.hpp"

namespace tandem {

RRTConnect::RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
                       const PlannerSettings& settings, std::unique_ptr<TargetSampler> sampler)
    : Planner(validator, start, goal, settings),
      start_tree_(validator.space(), settings.nearest_neighbors, start),
      goal_tree_(validator.space(), settings.nearest_neighbors, goal),
      start_steps_(range_, adaptive_floor(settings)),
      goal_steps_(range_, adaptive_floor(settings)),
      sampler_(sampler != nullptr ? std::move(sampler)
                                  : std::make_unique<UniformSampler>(validator.space())) {
  attach(start_tree_);
  attach(goal_tree_);
}

bool RRTConnect::iterate() {
  Tree& tree_a = extend_start_tree_ ? start_tree_ : goal_tree_;
  Tree& tree_b = extend_start_tree_ ? goal_tree_ : start_tree_;
  const bool a_is_start = extend_start_tree_;
  // 4. The next iteration extends the other tree.
  extend_start_tree_ = !extend_start_tree_;

  // 1. The targets.
  targets_.clear();
  sampler_->sample({stats().iterations, this, &rng_}, targets_);
  for (const Target& target : targets_) {
    if (add_tree(tree_a, tree_b, a_is_start, target))
      return true;
  }
  return false;
}

bool RRTConnect::add_tree(Tree& tree_a, Tree& tree_b, bool a_is_start, const Target& target) {
  // 2. Add_Tree: extend toward the target, then connect the other tree to q_new.
  const Extension ext = extend(tree_a, target.q, range_, validator_, settings_.extend,
                               target.source, a_is_start ? &start_steps_ : &goal_steps_);
  count_extension(ext.status);
  if (ext.status == ExtendStatus::trapped)
    return false;
  const Config q_new = tree_a.nodes[ext.node];
  Extension con;
  do {
    con = extend(tree_b, q_new, range_, validator_, settings_.extend, target.source);
  } while (con.status == ExtendStatus::advanced);
  if (con.status != ExtendStatus::reached)
    return false;

  // 3. The trees meet at q_new, present in both: keep it once.
  const NodeId start_node = a_is_start ? ext.node : con.node;
  const NodeId goal_node = a_is_start ? con.node : ext.node;
  solution_ = start_tree_.path_from_root(start_node);
  std::vector<Config> to_goal = goal_tree_.path_from_root(goal_node);
  solution_.insert(solution_.end(), to_goal.rbegin() + 1, to_goal.rend());
  return true;
}

}  // namespace tandem

#include "tandem/planning/rrt_connect.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "tandem/planning/extend.hpp"

namespace tandem {

RRTConnect::RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
                       const PlannerSettings& settings, std::unique_ptr<TargetSampler> sampler,
                       std::shared_ptr<const WorkspaceRoute> route)
    : Planner(validator, start, goal, settings),
      start_tree_(validator.space(), settings.nearest_neighbors, start),
      goal_tree_(validator.space(), settings.nearest_neighbors, goal),
      start_steps_(range_, adaptive_floor(settings)),
      goal_steps_(range_, adaptive_floor(settings)),
      sampler_(std::move(sampler)) {
  queries_origin_ = queries();
  attach(start_tree_);
  attach(goal_tree_);
  // The computer alone: along the workspace guide for a share `guide`, else uniform samples.
  if (sampler_ == nullptr && settings.guide > 0.0) {
    auto guided = std::make_unique<GuidedSampler>(validator.space(), validator.checker(), start,
                                                  goal, settings.guide, std::move(route));
    guided_ = guided.get();
    sampler_ = std::move(guided);
  } else if (sampler_ == nullptr) {
    sampler_ = std::make_unique<UniformSampler>(validator.space());
  }
  credits_ = sampler_->wants_credit();
  if (settings.passages > 0.0)
    islands_ = std::make_unique<PassageIslands>(validator,
                                                Rng(settings.seed ^ 0x6b6b6b6bc2b2ae35ULL).split());
}

bool RRTConnect::iterate() {
  Tree& tree_a = extend_start_tree_ ? start_tree_ : goal_tree_;
  Tree& tree_b = extend_start_tree_ ? goal_tree_ : start_tree_;
  const bool a_is_start = extend_start_tree_;
  // 4. The next iteration extends the other tree.
  extend_start_tree_ = !extend_start_tree_;

  if (passage_turn()) {
    // 5. An island's end instead of step 1's targets, if there is one to aim at.
    const std::uint64_t before = queries();
    const std::optional<IslandEnd> end = islands_->next_target(a_is_start ? 0 : 1);
    const bool met = end && aim_at_island(tree_a, tree_b, a_is_start, *end);
    island_queries_ += queries() - before;
    if (end)
      return met;
  }

  // 1. The targets (each tree's step floor lowered as the search's work grows).
  const std::uint64_t made = queries_so_far();
  start_steps_.relax(made);
  goal_steps_.relax(made);
  show_new_nodes();
  targets_.clear();
  if (credits_)
    credited_queries_ = queries();
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
  grown_ = grown(tree_a, ext);
  if (ext.status == ExtendStatus::trapped) {
    credit(target.source);
    return false;
  }
  return meet(tree_a, tree_b, a_is_start, ext.node, target.source);
}

void RRTConnect::credit(NodeSource source) {
  if (!credits_)
    return;
  const std::uint64_t now = queries();
  sampler_->credit(source, grown_, now - credited_queries_);
  credited_queries_ = now;
}

double RRTConnect::grown(const Tree& tree, const Extension& ext) const {
  // Only a sampler that is credited needs it: BiRRT's extensions do not pay for the distance.
  return credits_ && ext.added
             ? validator_.space().distance(tree.nodes[ext.near], tree.nodes[ext.node])
             : 0.0;
}

bool RRTConnect::meet(Tree& tree_a, Tree& tree_b, bool a_is_start, NodeId node, NodeSource source) {
  const Extension con = connect(tree_b, tree_a.nodes[node], source);
  // The other tree's way toward the new node is the target's doing too.
  credit(source);
  if (con.status != ExtendStatus::reached)
    return false;

  // 3. The trees meet at q_new, present in both: keep it once.
  const NodeId start_node = a_is_start ? node : con.node;
  const NodeId goal_node = a_is_start ? con.node : node;
  solution_ = start_tree_.path_from_root(start_node);
  std::vector<Config> to_goal = goal_tree_.path_from_root(goal_node);
  solution_.insert(solution_.end(), to_goal.rbegin() + 1, to_goal.rend());
  return true;
}

Extension RRTConnect::connect(Tree& tree, const Config& q, NodeSource source) {
  // q is copied first: it may be a node of the tree, whose storage the extensions grow.
  const Config target = q;
  Extension ext;
  do {
    ext = extend(tree, target, range_, validator_, settings_.extend, source);
    grown_ += grown(tree, ext);
  } while (ext.status == ExtendStatus::advanced);
  return ext;
}

void RRTConnect::show_new_nodes() {
  if (guided_ == nullptr || !guided_->covering())
    return;
  const std::array<const Tree*, 2> trees{&start_tree_, &goal_tree_};
  for (std::size_t side = 0; side < 2; ++side) {
    for (; shown_[side] < trees[side]->size(); ++shown_[side])
      guided_->cover(trees[side]->nodes[shown_[side]].t);
  }
}

std::uint64_t RRTConnect::queries() {
  const CollisionCounters& c = validator_.checker().counters();
  return c.state_checks + c.clearance_queries + c.distance_queries - queries_origin_;
}

bool RRTConnect::passage_turn() {
  if (islands_ == nullptr || stats().iterations < kPassageWarmup)
    return false;
  if (islands_->without_passages()) {
    islands_.reset();
    return false;
  }
  return static_cast<double>(island_queries_) < settings_.passages * static_cast<double>(queries());
}

bool RRTConnect::aim_at_island(Tree& tree_a, Tree& tree_b, bool a_is_start, const IslandEnd& end) {
  const int side = a_is_start ? 0 : 1;
  const Extension ext = connect(tree_a, islands_->end(end), NodeSource::random);
  count_extension(ext.status);
  if (ext.status != ExtendStatus::reached)
    return false;
  // The island joins T_a: its chain from the end reached to the other end.
  Island& island = islands_->island(end.island);
  island.joined[static_cast<std::size_t>(side)] = true;
  NodeId node = ext.node;
  const std::size_t n = island.chain.size();
  for (std::size_t k = 1; k < n; ++k)
    node = tree_a.add(island.chain[end.front ? k : n - 1 - k], node);
  return meet(tree_a, tree_b, a_is_start, node, NodeSource::random);
}

}  // namespace tandem

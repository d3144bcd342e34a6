#include "tandem/planning/rrt_connect.hpp"

#include "tandem/planning/extend.hpp"
#include "tandem/sampling/contact_sampler.hpp"

namespace tandem {

RRTConnect::RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
                       const PlannerSettings& settings, const Interaction* interaction)
    : Planner(validator, start, goal, settings, interaction),
      start_tree_(validator.space(), settings.nearest_neighbors, start),
      goal_tree_(validator.space(), settings.nearest_neighbors, goal),
      authority_rng_(settings.seed ^ 0xa5a5a5a5deadbeefULL),
      contact_rng_(settings.seed ^ 0x5a5a5a5a12345678ULL) {
  attach(start_tree_);
  attach(goal_tree_);
}

void RRTConnect::choose_targets() {
  targets_.clear();
  if (interaction_.feed != nullptr) {
    const InteractionSettings& s = interaction_settings();
    // Algorithm 1, lines 2-3: the operator has authority when a > alpha.
    if (authority_rng_.uniform01() > s.alpha) {
      const OperatorState* op = interaction_.feed->at(stats().iterations, this);
      if (op != nullptr) {
        ++operator_iterations_;
        const auto& frame = op->frame;
        if (s.contact && frame && frame->distance <= contact_distance(s, space_)) {
          // Algorithm 3, line 9: ContactSampling(P_o, P_n, N, q_device).
          ++contact_entries_;
          const double clearance = contact_clearance(s, space_);
          for (int i = 0; i < s.contact_samples; ++i) {
            if (auto q = sample_contact(*frame, op->device.q_device.q, space_, clearance,
                                        contact_rng_)) {
              targets_.push_back({*q, NodeSource::contact});
            }
          }
          if (!targets_.empty())
            return;
        }
        // Algorithm 3, lines 6-7.
        targets_.push_back({op->device.q_device, NodeSource::operator_});
        return;
      }
    }
  }
  targets_.push_back({space_.sample_uniform(rng_), NodeSource::random});
}

bool RRTConnect::iterate() {
  Tree& tree_a = extend_start_tree_ ? start_tree_ : goal_tree_;
  Tree& tree_b = extend_start_tree_ ? goal_tree_ : start_tree_;
  const bool a_is_start = extend_start_tree_;
  extend_start_tree_ = !extend_start_tree_;

  choose_targets();
  for (const Target& target : targets_) {
    // 2. Add_Tree: extend toward the target, then connect the other tree to q_new.
    const Extension ext =
        extend(tree_a, target.q, range_, validator_, settings_.extend, target.source);
    count_extension(ext.status);
    if (ext.status == ExtendStatus::trapped)
      continue;
    const Config q_new = tree_a.nodes[ext.node];
    Extension con;
    do {
      con = extend(tree_b, q_new, range_, validator_, settings_.extend, target.source);
    } while (con.status == ExtendStatus::advanced);
    if (con.status != ExtendStatus::reached)
      continue;

    // 3. The trees meet at q_new, present in both: keep it once.
    const NodeId start_node = a_is_start ? ext.node : con.node;
    const NodeId goal_node = a_is_start ? con.node : ext.node;
    solution_ = start_tree_.path_from_root(start_node);
    std::vector<Config> to_goal = goal_tree_.path_from_root(goal_node);
    solution_.insert(solution_.end(), to_goal.rbegin() + 1, to_goal.rend());
    return true;
  }
  return false;
}

}  // namespace tandem

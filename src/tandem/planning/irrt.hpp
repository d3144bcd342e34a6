#pragma once
// The Interactive RRT of
//   M. Taix and D. Flavigne, "Motion Planning with interactive devices", ECMS 2011, section V.
//
// One tree from the start, grown toward samples shot around the user. Each iteration:
//   1. q_user <- the operator's q_device; keep the user's recent path
//   2. L_near <- the p nodes nearest to q_user; COM <- their centre of mass, weighted by the labels
//      F_a <- COM - q_user          the guidance pseudo-force, published back to the device
//      F_u <- the user's motion     (displacement over the recent path)
//      F_r <- force_mix F_u + (1 - force_mix) F_a
//   3. q_rand <- the goal with probability goal_bias;
//      in +CS modes, a uniform sample once every x shots (x grows with the user's motion);
//      otherwise a Gaussian shot stretched along F_r, centred on the user (MAG) or on a point of
//      the user's recent path (PATH)
//   4. EXTEND(T, q_rand); the outcome is Collision (nothing added), Reached, or Obstacle (stopped
//      short)
//   5. Update_Labels: the extended node counts an extension, a collision, the distance covered;
//      the new node gets its distance-to-goal label
//   Solved when an extension toward the goal reaches it.
//
// Labels (the paper leaves their formulas open; these are tandem's):
//   distance label          d_i = distance(node, goal)
//   collision label         c_i = collisions_i / (extensions_i + 1)
//                                 x (1 - covered_i / (extensions_i x range)),   in [0, 1):
//                                 high for nodes whose extensions fail or cover little
//   centre-of-mass weight   w_i = (1 - c_i) / (d_i + D / 100),   D the space's maximum extent

#include <deque>

#include "tandem/interaction/interaction.hpp"
#include "tandem/planning/extend.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/space/twist.hpp"

namespace tandem {

class IRRT final : public Planner {
 public:
  struct NodeLabel {
    double distance_to_goal = 0.0;
    std::uint32_t extensions = 0;
    std::uint32_t collisions = 0;
    double covered = 0.0;
    double collision_label = 0.0;
  };

  /// Throws std::invalid_argument when the Interaction has no feed.
  IRRT(MotionValidator& validator, const Config& start, const Config& goal,
       const PlannerSettings& settings, const Interaction& interaction);

  std::string_view name() const override { return "irrt"; }
  std::vector<const Tree*> trees() const override { return {&tree_}; }
  const std::vector<NodeLabel>& labels() const { return labels_; }
  std::optional<double> node_label(std::size_t tree, NodeId node) const override {
    if (tree != 0 || node >= labels_.size())
      return std::nullopt;
    return labels_[node].distance_to_goal;
  }
  /// The pseudo-forces of the last iteration.
  const Twist& attractive_force() const { return f_a_; }
  const Twist& user_force() const { return f_u_; }
  const Twist& resulting_force() const { return f_r_; }

 protected:
  bool iterate() override;
  SamplerStats sampler_stats() const override;

 private:
  /// Step 5.
  void update_labels(const Extension& e);
  void update_user(const OperatorState& op);
  void update_forces(const Config& q_user, const InteractionSettings& s);
  Config shoot(const Config& q_user, const InteractionSettings& s, NodeSource& source,
               bool& toward_goal);

  Interaction interaction_;
  Tree tree_;
  std::vector<NodeLabel> labels_;
  std::deque<Config> user_path_;  ///< the user's recent positions, newest last
  std::uint64_t last_sequence_ = 0;
  Twist f_a_ = Twist::Zero(), f_u_ = Twist::Zero(), f_r_ = Twist::Zero();
  std::uint64_t shots_since_uniform_ = 0;
  Rng shot_rng_;
  std::vector<NodeId> near_;
  std::uint64_t operator_iterations_ = 0;
};

}  // namespace tandem

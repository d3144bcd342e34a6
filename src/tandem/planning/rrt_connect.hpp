#pragma once
// RRT-Connect, the bidirectional RRT ("BiRRT") of
//   J. J. Kuffner and S. M. LaValle, "RRT-Connect: An efficient approach to single-query path
//   planning", ICRA 2000,
// and, given an Interaction, the interactive BiRRT with contact of
//   N. Blin, M. Taix, P. Fillatreau, J.-Y. Fourquet, "I-RRT-C: Interactive Motion Planning with
//   Contact", IROS 2016 (Algorithms 1-3), and "Tuning Interaction in Motion Planning with Contact".
//
// Each iteration:
//   1. Choose the targets (Algorithm 3). a <- rand(0, 1):
//      - a <= alpha (the computer has authority): q_rand <- a uniform sample;
//      - a > alpha (the operator has authority): if contact sampling is on and the object at
//      q_device
//        is within d of an obstacle, N contact samples on the obstacle's tangent plane, with the
//        operator's orientation (Algorithm 2, ContactSampling); otherwise q_device.
//      Without an Interaction (or with alpha = 1) this is plain RRT-Connect: the authority draw has
//      its own random stream, so the tree is the same as BiRRT's for the same seed.
//   2. For each target, Add_Tree: EXTEND(T_a, target) -> q_new (unless TRAPPED), then CONNECT(T_b,
//   q_new):
//      EXTEND T_b toward q_new while it ADVANCES.
//   3. If T_b REACHED q_new, the trees meet: the path is start -> q_new -> goal.
//   4. Swap the roles of T_a and T_b.
// The tree to extend alternates between the start and the goal tree, as in OMPL's RRTConnect.

#include "tandem/planning/planner.hpp"

namespace tandem {

class RRTConnect final : public Planner {
 public:
  RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
             const PlannerSettings& settings, const Interaction* interaction = nullptr);

  std::string_view name() const override { return "birrt"; }
  std::vector<const Tree*> trees() const override { return {&start_tree_, &goal_tree_}; }

 protected:
  bool iterate() override;

 private:
  struct Target {
    Config q;
    NodeSource source;
  };
  /// Step 1: fills targets_.
  void choose_targets();

  Tree start_tree_;
  Tree goal_tree_;
  bool extend_start_tree_ = true;
  Rng authority_rng_;  ///< the authority draws, apart from the sampling stream
  Rng contact_rng_;    ///< contact samples
  std::vector<Target> targets_;
};

}  // namespace tandem

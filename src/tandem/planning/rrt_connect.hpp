#pragma once
// RRT-Connect, the bidirectional RRT ("BiRRT") of
//   J. J. Kuffner and S. M. LaValle, "RRT-Connect: An efficient approach to single-query path
//   planning", ICRA 2000,
// growing toward the targets of a TargetSampler: uniform samples (the computer alone), or authority
// sharing with contact sampling (the interactive BiRRT of Blin, Taix, Fillatreau, Fourquet,
// "I-RRT-C: Interactive Motion Planning with Contact", IROS 2016, Algorithm 3; see
// sampling/authority_sharing.hpp).
//
// Each iteration:
//   1. targets <- the sampler's targets for this iteration (one q_rand, or N contact samples);
//      the computer alone's q_rand is, for a share `guide` of its iterations after a warm-up,
//      drawn along a workspace guide until the trees have covered it (sampling/guided_sampler.hpp)
//   2. for each target q:
//        Add_Tree: q_new <- EXTEND(T_a, q), by q_near's adaptive step (adaptive_step.hpp; a
//                  fixed step for the interactive planners); if TRAPPED, next target
//        CONNECT(T_b, q_new): EXTEND T_b toward q_new while it ADVANCES
//   3.   if T_b REACHED q_new: the trees meet; the path is start -> q_new -> goal
//   4. swap the roles of T_a and T_b
//   5. (the computer alone, after kPassageWarmup iterations, while the islands have cost less than
//      a share `passages` of the collision queries) instead of steps 1-2's targets, an end of a
//      passage island (passage_islands.hpp): CONNECT(T_a, end); if T_a REACHES it, the island's
//      chain joins T_a, and CONNECT(T_b, ...) aims at the chain's other end. Without an island
//      to aim at, the iteration is the usual one.
// The tree to extend alternates between the start and the goal tree, as in OMPL's RRTConnect.

#include <array>
#include <memory>

#include "tandem/planning/adaptive_step.hpp"
#include "tandem/planning/extend.hpp"
#include "tandem/planning/passage_islands.hpp"
#include "tandem/planning/planner.hpp"
#include "tandem/sampling/guided_sampler.hpp"

namespace tandem {

class RRTConnect final : public Planner {
 public:
  /// Without a sampler, the computer alone's: along the workspace guide (`route`, if given, else
  /// found at the first iteration) for a share settings.guide, else uniform samples.
  RRTConnect(MotionValidator& validator, const Config& start, const Config& goal,
             const PlannerSettings& settings, std::unique_ptr<TargetSampler> sampler = nullptr,
             std::shared_ptr<const WorkspaceRoute> route = nullptr);

  std::string_view name() const override { return "rrt-connect"; }
  std::vector<const Tree*> trees() const override { return {&start_tree_, &goal_tree_}; }

 protected:
  bool iterate() override;
  SamplerStats sampler_stats() const override { return sampler_->stats(); }

 private:
  /// Iterations before the passage islands are first aimed at: most problems are solved sooner.
  static constexpr std::uint64_t kPassageWarmup = 2000;

  /// The sampler's feedback (TargetSampler::credit) after a target's extension and connection:
  /// the length the trees grew (grown_) and the queries it cost since the previous credit. Nothing
  /// for a sampler that does not want it.
  void credit(NodeSource source);
  /// The length of the motion an extension added to `tree` (0 if it added nothing, or when the
  /// sampler is not credited).
  double grown(const Tree& tree, const Extension& ext) const;
  /// Steps 2-3 for one target; true when the trees meet.
  bool add_tree(Tree& tree_a, Tree& tree_b, bool a_is_start, const Target& target);
  /// CONNECT (Kuffner & LaValle): EXTEND `tree` toward q while it ADVANCES; the last extension.
  Extension connect(Tree& tree, const Config& q, NodeSource source);
  /// CONNECT(T_b, T_a's node): step 3's meeting; true when the trees meet.
  bool meet(Tree& tree_a, Tree& tree_b, bool a_is_start, NodeId node, NodeSource source);
  /// Whether this iteration turns to the passage islands: after the warm-up, whenever the islands
  /// (making them and aiming at them) have cost less than `passages` of the checker's queries.
  bool passage_turn();
  /// The checker's queries (collision, clearance and distance) since this planner was made: a
  /// checker may have served earlier runs (a bench worker's), which must not change this one.
  std::uint64_t queries();
  /// Shows the trees' new nodes to the guided sampler (guided_sampler.hpp, step 3).
  void show_new_nodes();
  /// Aims T_a at an island's end and, if it gets there, takes the island; true when the trees meet.
  bool aim_at_island(Tree& tree_a, Tree& tree_b, bool a_is_start, const IslandEnd& end);

  Tree start_tree_;
  Tree goal_tree_;
  /// The steps of the extensions toward the targets (the connections take full steps).
  AdaptiveStep start_steps_;
  AdaptiveStep goal_steps_;
  bool extend_start_tree_ = true;
  std::unique_ptr<TargetSampler> sampler_;
  /// The computer alone's sampler when it follows a workspace guide (owned by sampler_), else null.
  GuidedSampler* guided_ = nullptr;
  /// The nodes of each tree (start, goal) shown to guided_ so far.
  std::array<std::size_t, 2> shown_{};
  std::vector<Target> targets_;
  /// Null when `passages` is 0 (and for the interactive planners).
  std::unique_ptr<PassageIslands> islands_;
  std::uint64_t queries_origin_ = 0;    ///< the checker's count when this planner was made
  std::uint64_t island_queries_ = 0;    ///< the checker's queries spent on islands
  bool credits_ = false;                ///< the sampler wants credit (wants_credit())
  std::uint64_t credited_queries_ = 0;  ///< queries() when the sampler was last credited
  /// The length the trees grew for the current target: its extension and the connection.
  double grown_ = 0.0;
};

}  // namespace tandem

#pragma once
// Authority sharing over an operator feed, with contact sampling as a strategy inside it:
//   N. Blin, M. Taix, P. Fillatreau, J.-Y. Fourquet, "I-RRT-C: Interactive Motion Planning with
//   Contact", IROS 2016, Algorithms 1-3, and "Tuning Interaction in Motion Planning with Contact".
//
// Algorithm 3 (Add_Tree's targets), each iteration:
//   1. a <- rand(0, 1)
//   2. if a <= alpha:                            the computer has authority
//   3.     q_rand <- a uniform sample
//   4. else:                                     the operator has authority
//   5.     read q_device and the nearest obstacle (P_o, P_n) from the operator's state
//   6.     if contact sampling is on and dist(q_device, obstacle) <= d:
//   7.         {q_i} <- ContactSampling(P_o, P_n, N, q_device)    (Algorithm 2)
//   8.     else:
//   9.         q_rand <- q_device
// Without an operator state yet, step 3 is taken. With auto_alpha, step 1's alpha is AutoAlpha's,
// learnt from the progress the planner credits to each side's iterations. The authority draw and
// the contact samples have random streams of their own, so the computer's samples are those of
// BiRRT for the same seed.
//
// Threading: the planner thread only; the live settings are read wait-free each iteration.

#include <optional>

#include "tandem/collision/collision_checker.hpp"
#include "tandem/collision/motion_validation.hpp"
#include "tandem/interaction/contact_frame.hpp"
#include "tandem/interaction/interaction.hpp"
#include "tandem/sampling/auto_alpha.hpp"
#include "tandem/sampling/target_sampler.hpp"

namespace tandem {

class AuthoritySharing final : public TargetSampler {
 public:
  /// `interaction.feed` is required; without `interaction.parameters`, `settings` hold throughout.
  /// `validation` is the planner's way of checking motions (it sets the default contact clearance).
  /// `checker` (the planner's, may be null) finds the surfaces of an edge or a corner when
  /// contact_surfaces > 1.
  AuthoritySharing(const SE3Space& space, const Interaction& interaction,
                   const InteractionSettings& settings, std::uint64_t seed,
                   MotionValidation validation, CollisionChecker* checker = nullptr);

  void sample(const SampleRequest& request, std::vector<Target>& out) override;
  SamplerStats stats() const override;
  bool wants_credit() const override { return true; }
  void credit(NodeSource source, double progress, std::uint64_t queries) override;

 private:
  /// Step 1's alpha: the setting, or AutoAlpha's once the last iteration's progress is recorded.
  double authority_share(const InteractionSettings& s);
  /// Steps 6-7: contact samples, or nothing when not in contact mode.
  bool contact_sampling(const OperatorState& op, const InteractionSettings& s,
                        std::vector<Target>& out);
  /// The surfaces contact samples lie above: the operator's frame, and with contact_surfaces > 1
  /// those of the other obstacle parts within d whose normals differ from it.
  std::vector<ContactFrame> contact_surfaces(const OperatorState& op, const InteractionSettings& s,
                                             double d);

  const SE3Space& space_;
  MotionValidation validation_;
  CollisionChecker* checker_;
  Interaction interaction_;
  InteractionSettings settings_;
  Rng authority_rng_;  ///< the authority draws, apart from the sampling stream
  Rng contact_rng_;    ///< contact samples
  SamplerStats stats_;
  AutoAlpha auto_alpha_;
  bool computer_turn_ = true;  ///< whose the current iteration is
  bool in_turn_ = false;       ///< an iteration was sampled and not yet recorded
  double turn_progress_ = 0.0;
  std::uint64_t turn_queries_ = 0;
};

}  // namespace tandem

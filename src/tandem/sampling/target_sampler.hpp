#pragma once
// Step 1 of the tree planners: what the tree grows toward in an iteration.
//
// A target sampler gives one or more targets per iteration: a uniform sample (the computer alone),
// or, with authority sharing, the operator's q_device or contact samples around it. RRT and
// RRT-Connect take a sampler; the human loop is a sampling strategy, not flags inside a planner
// ("the operator and contact samplers are just samplers").
//
// Determinism: a sampler draws its uniform samples from the planner's sampling stream (passed in
// each call, VAMP's way) and any other randomness from streams of its own seeded from the run's
// seed, so the same seed and operator give the same targets.
//
// Threading: sample() runs on the planner thread only.

#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "tandem/core/rng.hpp"
#include "tandem/interaction/operator_feed.hpp"
#include "tandem/space/se3_space.hpp"

namespace tandem {

/// Where a node's target came from: the tree's root, a uniform sample, the operator (q_device, or a
/// sample around it), or contact sampling. Nodes added while connecting carry the source of the
/// node they connect to.
enum class NodeSource : std::uint8_t { root, random, operator_, contact };
inline constexpr std::size_t kNodeSources = 4;
std::string_view to_string(NodeSource source);

struct Target {
  Config q;
  NodeSource source = NodeSource::random;
};

/// What a sampler is given each iteration.
struct SampleRequest {
  std::uint64_t iteration = 0;           ///< the planner's iteration count (operator time in ticks)
  const RoadmapView* roadmap = nullptr;  ///< what a watching simulated operator looks at
  Rng* rng = nullptr;                    ///< the planner's sampling stream
};

/// Counters a sampler keeps for the planner's statistics.
struct SamplerStats {
  double operator_time_s = 0.0;           ///< planner-thread time computing operator states
  std::uint64_t operator_iterations = 0;  ///< iterations in which the operator had authority
  std::uint64_t contact_entries = 0;      ///< iterations in contact mode
  /// Authority sharing's alpha in the latest iteration (NaN for a sampler without one).
  double alpha = std::numeric_limits<double>::quiet_NaN();
};

class TargetSampler {
 public:
  virtual ~TargetSampler() = default;
  /// Appends this iteration's targets (at least one) to `out`.
  virtual void sample(const SampleRequest& request, std::vector<Target>& out) = 0;
  virtual SamplerStats stats() const { return {}; }
  /// The planner's feedback on this iteration's targets, once per target: `progress`, the length
  /// of motion its extension and the other tree's connection toward the new node added to the
  /// trees (scene units, 0 if nothing was added), and what they cost: the collision queries since
  /// the previous credit (the first credit of an iteration includes the sampler's own queries).
  virtual bool wants_credit() const { return false; }
  virtual void credit(NodeSource source, double progress, std::uint64_t queries) {
    (void)source;
    (void)progress;
    (void)queries;
  }
};

/// The computer alone: one uniform sample of the space per iteration.
class UniformSampler final : public TargetSampler {
 public:
  explicit UniformSampler(const SE3Space& space) : space_(space) {}
  void sample(const SampleRequest& request, std::vector<Target>& out) override {
    out.push_back({space_.sample_uniform(*request.rng), NodeSource::random});
  }

 private:
  const SE3Space& space_;
};

}  // namespace tandem

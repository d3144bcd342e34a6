#pragma once
// Passage islands: stretches of valid motion through the workspace's narrow tubes, made where the
// tubes are and offered to RRT-Connect as targets (the narrow-passage strategy of the computer
// alone).
//
// Where the part can pass a tube of free space only along its axis (bugtrap's funnel), a uniform
// sample lies in the passage with a vanishing probability, and a tree enters it only by chance.
// Workspace-guided sampling (Kurniawati & Hsu, "Workspace importance sampling for probabilistic
// roadmap planning", IROS 2004) puts samples where the workspace is narrow instead; seeding
// local trees there is Strandberg's RRT with local trees (ICRA 2004). Here:
//   1. the tubes' axes come from the distance grid (collision/passages.hpp), tubes narrower than
//      the part's longest half extent (wider ones are open space for it);
//   2. a passage configuration: the part's reference point on an axis cell, its longest principal
//      axis along the tube's (either sign), a random roll about it; kept if valid. The cell is
//      drawn from a random one of kBands bands of clearance (equal widths in its logarithm), then
//      uniformly in the band: the narrowest tubes, the ones the trees miss, are few cells among
//      many wider ones;
//   3. the part slides along the tube's axis both ways from there, straight motions of half its
//      longest half extent checked by the validator, until one is invalid, ends nearer than the
//      sweep's stop or leaves the bounds, at most four half extents each way; each side ends at
//      its most open configuration (largest clearance bound), where a tree reaches it most easily;
//   4. the island is that chain; a tree that reaches one of its ends takes the whole chain
//      (rrt_connect.hpp), which carries it through the passage.
// Every configuration and motion of a chain is checked as the planner checks its own, so an island
// changes where the trees grow, never what is valid.
//
// Determinism: islands come from a stream seeded from the run's seed, in the planner's order.
// Threading: one per planner, used on its thread only.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tandem/collision/motion_validator.hpp"
#include "tandem/collision/passages.hpp"
#include "tandem/core/rng.hpp"

namespace tandem {

struct Island {
  std::vector<Config> chain;     ///< every motion between neighbours is valid
  std::array<bool, 2> joined{};  ///< taken by the start tree [0], the goal tree [1]
  std::size_t band = 0;          ///< its passage's band of clearance
};

struct IslandEnd {
  std::size_t island = 0;
  bool front = true;  ///< chain.front(), else chain.back()
};

class PassageIslands {
 public:
  /// Islands are at most this many per band of clearance; past it, a new island replaces one of
  /// its band that no tree has taken (so the few narrowest islands are not crowded out).
  static constexpr std::size_t kIslandsPerBand = 8;
  /// Step 2's bands of clearance.
  static constexpr std::size_t kBands = 8;

  PassageIslands(MotionValidator& validator, std::uint64_t seed);

  /// An end of an island that `tree` (0 start, 1 goal) has not taken, making a new island first
  /// half of the time (always while there is none); nothing when the problem has no passage
  /// (no grid, a planar space, no tube) or no island could be made.
  std::optional<IslandEnd> next_target(int tree);
  Island& island(std::size_t i) { return islands_[i]; }
  const Config& end(const IslandEnd& e) const {
    const auto& c = islands_[e.island].chain;
    return e.front ? c.front() : c.back();
  }
  std::size_t size() const { return islands_.size(); }
  /// Passage cells found (after the first next_target()).
  std::size_t passage_count() const { return passages_ ? passages_->size() : 0; }
  /// The passages are found (on the first call) and there are none.
  bool without_passages() {
    if (!passages_)
      find();
    return passages_->empty();
  }

 private:
  void find();
  bool make_island();
  /// A passage's index, and its band.
  std::pair<std::size_t, std::size_t> draw_passage();
  /// An island's configurations keep at least the exact sweep's stop from the obstacles (a node
  /// nearer makes every motion from it expensive, as motion_validation.hpp says).
  double margin() const;
  bool open_enough(const Config& q);
  void keep(Island island);
  /// Step 3 for one side: the valid configurations along `direction` from q, q excluded, up to
  /// the most open one.
  std::vector<Config> slide(const Config& q, const Eigen::Vector3d& direction);

  MotionValidator& validator_;
  Rng rng_;
  ObjectExtent extent_;
  std::optional<std::vector<Passage>> passages_;
  std::vector<Island> islands_;
  /// The passages' indices by band of clearance (empty bands dropped).
  std::vector<std::vector<std::size_t>> bands_;
};

}  // namespace tandem

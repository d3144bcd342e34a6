#pragma once
// Collision and distance queries of the moving object against the scene's obstacles (FCL behind
// tandem's own interface: no FCL type appears here).
//
// Threading: one CollisionChecker per thread. clone() gives another thread its own checker; clones
// share the immutable geometry (BVH models, primitives, the distance grid) and nothing else, so
// they can run concurrently.
//
// Conventions: configurations are poses of the object frame in the world frame (X_WO); all points
// are in the world frame; distances are in the scene's length unit and never negative. FCL's mesh
// distance is not signed (fcl #221, #491): objects that overlap report in_collision = true and
// distance 0, and their nearest points are unspecified.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>

#include "tandem/scene/scene.hpp"
#include "tandem/space/bounds.hpp"
#include "tandem/space/config.hpp"

namespace tandem {

struct CollisionCounters {
  std::uint64_t state_checks = 0;       ///< is_collision_free() calls
  std::uint64_t distance_queries = 0;   ///< nearest_obstacle() calls
  std::uint64_t clearance_queries = 0;  ///< clearance_bound() calls
  std::uint64_t fcl_errors =
      0;  ///< exceptions thrown by FCL and caught here (counted as collision)
  std::uint64_t prefilter_answers = 0;  ///< queries the distance grid answered without FCL
  /// What the queries did, counted the same on every machine and under any load: pairs of boxes
  /// and of triangles tested in tandem's walks of the OBB trees, spheres the pre-filter opened,
  /// and calls to FCL (for the parts that are not two meshes).
  std::uint64_t box_tests = 0;
  std::uint64_t triangle_tests = 0;
  std::uint64_t spheres_opened = 0;
  std::uint64_t fcl_calls = 0;
};

/// The work of the queries counted in `c`, in tests of a pair of boxes: each count weighted by
/// what one costs, so that the work grows with the queries' time as a clock would, but does not
/// depend on the machine. Fitted to the times of single queries (one thread, BiRRT, seeds 1-2):
/// a box test 37-48 ns, a pair of triangles 100-220, an opened sphere 46-83, a query's fixed part
/// 300-540 (Apartment's 120 obstacles: 2 000) on cubicles, alpha-1.5, Apartment and Twistycool;
/// with the weights the work then took 36-44 ns a unit on all four.
std::uint64_t query_work(const CollisionCounters& c);

struct NearestObstacle {
  bool in_collision = false;
  double distance = 0.0;                                        ///< >= 0; 0 when in collision
  Eigen::Vector3d point_on_object = Eigen::Vector3d::Zero();    ///< P_n, world frame
  Eigen::Vector3d point_on_obstacle = Eigen::Vector3d::Zero();  ///< P_o, world frame
  std::size_t obstacle = 0;                                     ///< index into Scene::obstacles
};

struct ObjectExtent {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half_extents = Eigen::Vector3d::Zero();
};

class DistanceGrid;
class GuideBlocks;

/// How a query finds the obstacle parts to hand to FCL: by testing every part's box in turn
/// (linear), or through the broad phase of their boxes (obstacle_broad_phase.hpp: a grid for
/// overlaps where the boxes suit one, a tree otherwise and for distances). The answers are the
/// same (the tree only skips parts the box test would skip, and visits the rest in the scene's
/// order where the order shows in an answer); automatic takes the tree where it measures faster
/// (bench/scaling.cpp): from CollisionChecker::kBroadPhaseFrom obstacle parts on, and for
/// nearest_obstacle(), whose search goes nearest parts first, from kNearestThroughTreeFrom.
enum class BroadPhase { automatic, linear, tree };

class CollisionChecker {
 public:
  /// Builds FCL models for every part (BVHModel<OBBRSS> and BVHModel<OBB> for meshes, FCL
  /// primitives otherwise).
  /// Throws InputError if a primitive has a non-positive or non-finite size.
  explicit CollisionChecker(const Scene& scene);
  ~CollisionChecker();
  CollisionChecker(CollisionChecker&&) noexcept;
  CollisionChecker& operator=(CollisionChecker&&) noexcept;

  /// A checker for another thread: shares geometry, has its own counters.
  CollisionChecker clone() const;

  /// True when the object at q touches no obstacle. An FCL exception counts as a collision.
  bool is_collision_free(const Config& q);

  /// The obstacle nearest to the object at q, with the nearest points.
  NearestObstacle nearest_obstacle(const Config& q);

  /// For each part of an obstacle (a shape, or a mesh) within `within` of the object at q, its
  /// nearest points to the object, nearest first: the surfaces the object is near (several near an
  /// edge or a corner made of several parts; one part's own edge counts as one). Empty when the
  /// object touches an obstacle.
  std::vector<NearestObstacle> nearest_surfaces(const Config& q, double within);

  /// A lower bound on the distance between the object at q and every obstacle, capped: the result
  /// c satisfies c <= min(cap, true distance), and c < cap only when something is closer than cap.
  /// It is <= 0 when the object collides (FCL's mesh distance is 0 for intersecting triangles,
  /// negative for penetrating primitives); an FCL exception gives 0. Cheaper than
  /// nearest_obstacle(): the search prunes with a relative error (kClearanceRelativeError) and
  /// every pair of bounding volumes farther than the cap, and boxes prune whole pairs of parts;
  /// two meshes are searched through their OBB trees (mesh_proximity.hpp), other pairs by FCL.
  /// The continuous motion validation certifies motions with it.
  double clearance_bound(const Config& q, double cap) { return clearance_bound(q, cap, cap); }
  /// The same, with FCL asked only up to fcl_cap (<= cap): the distance grid, when built, answers
  /// up to cap in a few memory reads; FCL's work grows with its cap.
  double clearance_bound(const Config& q, double cap, double fcl_cap);

  /// FCL's relative error in clearance_bound(): true distance >= returned / (1 + error).
  static constexpr double kClearanceRelativeError = 0.25;

  /// The largest distance from the object frame's origin (the configuration's reference point) to
  /// any point of the object: no point moves more than |dt| + angle * radius in a motion that
  /// translates by dt and turns by angle about a fixed axis.
  double object_radius() const;

  /// The object's principal axes (columns, in the object frame, the longest extent first) and its
  /// half extents along them about the reference point, from its vertices (box corners for
  /// primitives).
  ObjectExtent object_extent() const;

  /// Builds the pre-filter (distance_grid.hpp, sphere_tree.hpp) for an object whose reference
  /// point stays inside `bounds`, with cells of `spacing`: from then on is_collision_free() and
  /// clearance_bound() consult it first and pass to FCL only what it cannot certify. It only
  /// certifies "free" or "at least this far", never a collision, so no answer changes but the
  /// clearance bounds (which may come out larger, never above the true distance). Clones made
  /// afterwards share it. Builds nothing when the last grid built has the same bounds and
  /// spacing (also after drop_distance_grid()).
  void use_distance_grid(const Bounds& bounds, double spacing);
  /// Back to FCL alone (for comparisons); the grid is kept for a later use_distance_grid().
  void drop_distance_grid();
  bool has_distance_grid() const;
  /// The distance grid in use, or null (immutable; shared with the clones).
  const DistanceGrid* distance_grid() const;
  /// The workspace guide's coarse blocks of that grid inside its bounds (workspace_guide.hpp),
  /// built with it, or null without a grid (immutable; shared with the clones).
  const GuideBlocks* guide_blocks() const;

  /// The broad phase for the queries of this checker (clones made afterwards take it).
  void use_broad_phase(BroadPhase broad_phase);
  /// Whether the queries go through the tree of obstacle boxes.
  bool uses_tree() const;
  static constexpr std::size_t kBroadPhaseFrom = 16;
  static constexpr std::size_t kNearestThroughTreeFrom = 2;

  std::size_t obstacle_count() const;
  const std::string& obstacle_name(std::size_t index) const;

  const CollisionCounters& counters() const;
  void reset_counters();
  /// Adds another checker's counts to this one's (a QueryHelper's queries made for this one).
  void add_counters(const CollisionCounters& other);

 private:
  struct Impl;
  explicit CollisionChecker(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tandem

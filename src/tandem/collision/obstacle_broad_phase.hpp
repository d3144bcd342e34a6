#pragma once
// The broad phase over the scene's static obstacle parts: FCL's dynamic AABB tree
// (DynamicAABBTreeCollisionManager) of their world boxes, built once, and a uniform grid of them
// (box_grid.hpp) where they suit one. A query gives a box (a part of the moving object, posed) and
// visits the obstacle parts whose boxes overlap it (through the grid if there is one: its cost does
// not grow with the number of parts, the tree's descent does), or those nearer than a bound that
// the visitor lowers as it finds nearer parts, nearer subtrees first (through the tree).
// The narrow phase (FCL on the parts' own models) stays with the caller: the tree only chooses
// which parts to hand to it, so a query's exact answer is the linear loop's (collision_checker).
//
// Threading: immutable once built; any number of threads may query it (each query builds its own
// FCL query object).

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

#include "tandem/collision/box_grid.hpp"

namespace tandem {

class ObstacleBroadPhase {
 public:
  using Box = BoxGrid::Box;

  /// The tree over the boxes (in the world frame; a box's index is its part's).
  explicit ObstacleBroadPhase(const std::vector<Box>& boxes);
  ~ObstacleBroadPhase();
  ObstacleBroadPhase(const ObstacleBroadPhase&) = delete;
  ObstacleBroadPhase& operator=(const ObstacleBroadPhase&) = delete;

  /// Calls visit(i) once for every box i that overlaps `query` (touching counts), in no given
  /// order, until a call returns true; returns whether one did.
  template <class Visit>
  bool overlapping(const Box& query, Visit&& visit) const {
    return overlapping(query, erase(visit), [](void* v, std::size_t i, double&) {
      return (*static_cast<std::remove_reference_t<Visit>*>(v))(i);
    });
  }

  /// Calls visit(i, bound) for boxes i whose distance to `query` is below `bound` (nearer
  /// subtrees first; a box may also be visited at a distance equal to or above it, so the visitor
  /// checks what it needs), until a call returns true; the visitor may lower `bound`, which prunes
  /// the rest. Returns whether a call returned true.
  template <class Visit>
  bool nearer_than(const Box& query, double& bound, Visit&& visit) const {
    return nearer_than(query, bound, erase(visit), [](void* v, std::size_t i, double& b) {
      return (*static_cast<std::remove_reference_t<Visit>*>(v))(i, b);
    });
  }

 private:
  template <class Visit>
  static void* erase(Visit& visit) {
    return const_cast<void*>(static_cast<const void*>(std::addressof(visit)));
  }
  using Trampoline = bool (*)(void* visit, std::size_t index, double& bound);
  bool overlapping(const Box& query, void* visit, Trampoline call) const;
  bool nearer_than(const Box& query, double& bound, void* visit, Trampoline call) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tandem

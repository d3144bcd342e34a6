#include "tandem/collision/obstacle_broad_phase.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/sphere.h>

#include <cstdint>
#include <limits>
#include <optional>

namespace tandem {
namespace {

/// The boxes are compared with a margin so that the tree's candidates include every part the
/// linear loop would test, whatever the rounding of FCL's box tests: the caller's own test
/// decides.
constexpr double kMargin = 1e-9;

double margin_of(const ObstacleBroadPhase::Box& box) {
  return kMargin * (1.0 + box.min.cwiseAbs().maxCoeff() + box.max.cwiseAbs().maxCoeff());
}

/// The box grown by its margin on every side, as the tree and the grid hold and query it.
ObstacleBroadPhase::Box inflated(const ObstacleBroadPhase::Box& box) {
  const Eigen::Vector3d margin = Eigen::Vector3d::Constant(margin_of(box));
  return {box.min - margin, box.max + margin};
}

/// An FCL collision object whose world box is set, not computed from its geometry (FCL's is a
/// sphere's box for a turned object; the tree holds the parts' tight boxes). Its geometry is never
/// used: the narrow phase is the caller's.
class BoxObject : public fcl::CollisionObjectd {
 public:
  BoxObject(const std::shared_ptr<fcl::CollisionGeometryd>& placeholder,
            const ObstacleBroadPhase::Box& box)
      : fcl::CollisionObjectd(placeholder) {
    set_box(box);
  }
  void set_box(const ObstacleBroadPhase::Box& box) {
    aabb.min_ = box.min;
    aabb.max_ = box.max;
  }
};

/// The query's object: one per thread, its box set for each query, so that a query allocates
/// nothing.
BoxObject& query_object(const ObstacleBroadPhase::Box& box) {
  thread_local BoxObject object(std::make_shared<fcl::Sphered>(1.0), box);
  object.set_box(inflated(box));
  return object;
}

std::size_t index_of(const fcl::CollisionObjectd* o) {
  return static_cast<std::size_t>(reinterpret_cast<std::uintptr_t>(o->getUserData()));
}

/// What FCL's callbacks get: the caller's visitor, its bound, and whether it asked to stop.
struct Query {
  void* visit;
  bool (*call)(void*, std::size_t, double&);
  double* bound;
  bool stopped = false;

  bool visit_part(const fcl::CollisionObjectd* o) {
    stopped = call(visit, index_of(o), *bound);
    return stopped;
  }
};

}  // namespace

// (FCL 0.7's array-backed variant, DynamicAABBTreeCollisionManager_Array, measured no faster here
// and leaks what registerObjects() allocates: the journal fuzz target's leak check found it.)
struct ObstacleBroadPhase::Impl {
  std::shared_ptr<fcl::CollisionGeometryd> placeholder = std::make_shared<fcl::Sphered>(1.0);
  std::vector<std::unique_ptr<BoxObject>> objects;
  fcl::DynamicAABBTreeCollisionManagerd tree;
  /// The overlap queries' index where the boxes suit a grid (the tree's descent costs most of a
  /// yes/no check among thousands of parts); the tree's otherwise, and always for distances.
  std::optional<BoxGrid> grid;
};

ObstacleBroadPhase::ObstacleBroadPhase(const std::vector<Box>& boxes)
    : impl_(std::make_unique<Impl>()) {
  std::vector<Box> grown;
  grown.reserve(boxes.size());
  for (const Box& b : boxes)
    grown.push_back(inflated(b));
  std::vector<fcl::CollisionObjectd*> registered;
  for (std::size_t i = 0; i < grown.size(); ++i) {
    auto object = std::make_unique<BoxObject>(impl_->placeholder, grown[i]);
    object->setUserData(reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    registered.push_back(object.get());
    impl_->objects.push_back(std::move(object));
  }
  impl_->tree.registerObjects(registered);
  impl_->tree.setup();
  impl_->grid = BoxGrid::build(grown);
}

ObstacleBroadPhase::~ObstacleBroadPhase() = default;

bool ObstacleBroadPhase::overlapping(const Box& query, void* visit, Trampoline call) const {
  double unused = 0.0;
  if (impl_->grid) {
    return impl_->grid->overlapping(inflated(query),
                                    [&](std::size_t i) { return call(visit, i, unused); });
  }
  Query q{visit, call, &unused};
  impl_->tree.collide(&query_object(query), &q,
                      [](fcl::CollisionObjectd* o, fcl::CollisionObjectd*, void* data) {
                        return static_cast<Query*>(data)->visit_part(o);
                      });
  return q.stopped;
}

bool ObstacleBroadPhase::nearer_than(const Box& query, double& bound, void* visit,
                                     Trampoline call) const {
  Query q{visit, call, &bound};
  impl_->tree.distance(
      &query_object(query), &q,
      [](fcl::CollisionObjectd* o, fcl::CollisionObjectd*, void* data, double& dist) {
        auto* self = static_cast<Query*>(data);
        const bool stop = self->visit_part(o);
        // FCL prunes the subtrees at least `dist` away: the visitor's bound, with room for the
        // boxes' margins (the caller's test decides).
        const double b = *self->bound;
        dist = b < std::numeric_limits<double>::max() / 2 ? b * (1.0 + kMargin) + kMargin
                                                          : std::numeric_limits<double>::max();
        return stop;
      });
  return q.stopped;
}

}  // namespace tandem

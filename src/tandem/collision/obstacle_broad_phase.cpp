#include "tandem/collision/obstacle_broad_phase.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/sphere.h>

#include <cstdint>
#include <limits>

namespace tandem {
namespace {

/// The boxes are compared with a margin so that the tree's candidates include every part the
/// linear loop would test, whatever the rounding of FCL's box tests: the caller's own test
/// decides.
constexpr double kMargin = 1e-9;

double margin_of(const ObstacleBroadPhase::Box& box) {
  return kMargin * (1.0 + box.min.cwiseAbs().maxCoeff() + box.max.cwiseAbs().maxCoeff());
}

/// An FCL collision object whose world box is set, not computed from its geometry (FCL's is a
/// sphere's box for a turned object; the tree holds the parts' tight boxes). Its geometry is never
/// used: the narrow phase is the caller's.
class BoxObject : public fcl::CollisionObjectd {
 public:
  BoxObject(const std::shared_ptr<fcl::CollisionGeometryd>& placeholder,
            const ObstacleBroadPhase::Box& box, double margin)
      : fcl::CollisionObjectd(placeholder) {
    set_box(box, margin);
  }
  void set_box(const ObstacleBroadPhase::Box& box, double margin) {
    aabb.min_ = box.min - Eigen::Vector3d::Constant(margin);
    aabb.max_ = box.max + Eigen::Vector3d::Constant(margin);
  }
};

/// The query's object: one per thread, its box set for each query (a new FCL object per query
/// costs as much as the search of a small tree).
BoxObject& query_object(const ObstacleBroadPhase::Box& box) {
  thread_local BoxObject object(std::make_shared<fcl::Sphered>(1.0), box, 0.0);
  object.set_box(box, margin_of(box));
  return object;
}

std::size_t index_of(const fcl::CollisionObjectd* o) {
  return static_cast<std::size_t>(reinterpret_cast<std::uintptr_t>(o->getUserData()));
}

struct Query {
  void* visit;
  bool (*call)(void*, std::size_t, double&);
  double* bound;
};

}  // namespace

// (FCL 0.7's array-backed variant, DynamicAABBTreeCollisionManager_Array, measured no faster here
// and leaks what registerObjects() allocates: the journal fuzz target's leak check found it.)
struct ObstacleBroadPhase::Impl {
  std::shared_ptr<fcl::CollisionGeometryd> placeholder = std::make_shared<fcl::Sphered>(1.0);
  std::vector<std::unique_ptr<BoxObject>> objects;
  fcl::DynamicAABBTreeCollisionManagerd tree;
};

ObstacleBroadPhase::ObstacleBroadPhase(const std::vector<Box>& boxes)
    : impl_(std::make_unique<Impl>()) {
  std::vector<fcl::CollisionObjectd*> registered;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    auto object = std::make_unique<BoxObject>(impl_->placeholder, boxes[i], margin_of(boxes[i]));
    object->setUserData(reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    registered.push_back(object.get());
    impl_->objects.push_back(std::move(object));
  }
  impl_->tree.registerObjects(registered);
  impl_->tree.setup();
}

ObstacleBroadPhase::~ObstacleBroadPhase() = default;

std::size_t ObstacleBroadPhase::size() const {
  return impl_->objects.size();
}

bool ObstacleBroadPhase::overlapping(const Box& query, void* visit, Trampoline call) const {
  BoxObject& q = query_object(query);
  double unused = 0.0;
  Query data{visit, call, &unused};
  bool stopped = false;
  struct Context {
    Query* query;
    bool* stopped;
  } context{&data, &stopped};
  impl_->tree.collide(&q, &context, [](fcl::CollisionObjectd* o, fcl::CollisionObjectd*, void* c) {
    auto* ctx = static_cast<Context*>(c);
    *ctx->stopped = ctx->query->call(ctx->query->visit, index_of(o), *ctx->query->bound);
    return *ctx->stopped;
  });
  return stopped;
}

bool ObstacleBroadPhase::nearer_than(const Box& query, double& bound, void* visit,
                                     Trampoline call) const {
  BoxObject& q = query_object(query);
  Query data{visit, call, &bound};
  bool stopped = false;
  struct Context {
    Query* query;
    bool* stopped;
  } context{&data, &stopped};
  impl_->tree.distance(
      &q, &context, [](fcl::CollisionObjectd* o, fcl::CollisionObjectd*, void* c, double& dist) {
        auto* ctx = static_cast<Context*>(c);
        const Query& query_of = *ctx->query;
        *ctx->stopped = query_of.call(query_of.visit, index_of(o), *query_of.bound);
        // FCL prunes the subtrees at least `dist` away: the visitor's bound, with room for the
        // boxes' margins (the caller's test decides).
        const double b = *query_of.bound;
        dist = b < std::numeric_limits<double>::max() / 2 ? b * (1.0 + kMargin) + kMargin
                                                          : std::numeric_limits<double>::max();
        return *ctx->stopped;
      });
  return stopped;
}

}  // namespace tandem

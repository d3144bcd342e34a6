// size: the checker and its queries (collision, clearance, nearest points) share its private FCL
// geometry; splitting them would expose it.
#include "tandem/collision/collision_checker.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tandem/collision/distance_grid.hpp"
#include "tandem/collision/mesh_proximity.hpp"
#include "tandem/collision/obstacle_broad_phase.hpp"
#include "tandem/collision/sphere_tree.hpp"
#include "tandem/collision/workspace_guide.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using Geom = fcl::CollisionGeometryd;

/// An axis-aligned box in some frame, as centre and half extents.
struct Box3 {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d half = Eigen::Vector3d::Zero();

  Box3 transformed(const Eigen::Isometry3d& X) const {
    return {X * centre, X.linear().cwiseAbs() * half};
  }
  bool overlaps(const Box3& o) const {
    return ((centre - o.centre).cwiseAbs().array() <= (half + o.half).array()).all();
  }
  /// Lower bound on the distance between anything inside the two boxes.
  double distance_to(const Box3& o) const {
    return ((centre - o.centre).cwiseAbs() - half - o.half).cwiseMax(0.0).norm();
  }
};

void check_positive(double v, const std::string& body, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw InputError(
        body, std::string(what) + " must be a positive finite number, got " + std::to_string(v));
  }
}

/// The FCL models of a part: for a mesh, an OBBRSS tree for nearest points and an OBB tree for
/// yes/no collision (faster: moveit2 #2534; measured with tandem-check-costs) and clearance bounds
/// (mesh_proximity.hpp); for a primitive, one shape.
struct FclModels {
  std::shared_ptr<Geom> distance;
  std::shared_ptr<Geom> collision;
};

template <class BV>
std::shared_ptr<Geom> make_bvh(const TriangleMesh& mesh, const std::vector<fcl::Triangle>& tris) {
  auto model = std::make_shared<fcl::BVHModel<BV>>();
  model->beginModel(static_cast<int>(tris.size()), static_cast<int>(mesh.vertices.size()));
  model->addSubModel(mesh.vertices, tris);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

FclModels make_models(const Geometry& g, const std::string& body) {
  struct Visitor {
    const std::string& body;
    std::shared_ptr<Geom> shape(std::shared_ptr<Geom> geom) const {
      geom->computeLocalAABB();
      return geom;
    }
    FclModels operator()(const Box& b) const {
      for (int i = 0; i < 3; ++i)
        check_positive(b.size[i], body, "box size");
      auto geom = shape(std::make_shared<fcl::Boxd>(b.size));
      return {geom, geom};
    }
    FclModels operator()(const Sphere& s) const {
      check_positive(s.radius, body, "sphere radius");
      auto geom = shape(std::make_shared<fcl::Sphered>(s.radius));
      return {geom, geom};
    }
    FclModels operator()(const Cylinder& c) const {
      check_positive(c.radius, body, "cylinder radius");
      check_positive(c.length, body, "cylinder length");
      auto geom = shape(std::make_shared<fcl::Cylinderd>(c.radius, c.length));
      return {geom, geom};
    }
    FclModels operator()(const MeshShape& m) const {
      if (!m.mesh || m.mesh->triangles.empty())
        throw InputError(m.source, "the mesh has no triangles");
      std::vector<fcl::Triangle> tris;
      tris.reserve(m.mesh->triangles.size());
      const std::size_t n = m.mesh->vertices.size();
      for (const auto& t : m.mesh->triangles) {
        // Indices are validated by sanitize_mesh(); FCL's addSubModel does not check them.
        if (t[0] >= n || t[1] >= n || t[2] >= n)
          throw InputError(m.source, "triangle index out of range");
        tris.emplace_back(t[0], t[1], t[2]);
      }
      return {make_bvh<fcl::OBBRSSd>(*m.mesh, tris), make_bvh<fcl::OBBd>(*m.mesh, tris)};
    }
  };
  return std::visit(Visitor{body}, g);
}

bool is_mesh(const Geometry& g) {
  return std::holds_alternative<MeshShape>(g);
}
bool is_sphere(const Geometry& g) {
  return std::holds_alternative<Sphere>(g);
}

Box3 local_box(const Geom& g) {
  const auto& aabb = g.aabb_local;
  return {0.5 * (aabb.min_ + aabb.max_), 0.5 * (aabb.max_ - aabb.min_)};
}

struct FclPart {
  std::shared_ptr<const Geom> geometry;            ///< FCL's distances (OBBRSS for a mesh)
  std::shared_ptr<const Geom> collision_geometry;  ///< yes/no, clearance bounds (OBB for a mesh)
  Eigen::Isometry3d pose;                          ///< X_BP
  bool pose_is_identity;
  bool is_mesh;
  bool is_sphere;
  Box3 box;              ///< for the object: in the part frame; for obstacles: in the world frame
  std::size_t obstacle;  ///< owning obstacle (obstacle parts only)
};

/// The OBB tree of a mesh part.
const fcl::BVHModel<fcl::OBBd>& obb_tree(const FclPart& mesh_part) {
  return static_cast<const fcl::BVHModel<fcl::OBBd>&>(*mesh_part.collision_geometry);
}

struct SharedGeometry {
  std::vector<FclPart> object;
  std::vector<FclPart> obstacles;
  std::vector<std::string> obstacle_names;
  double object_radius = 0.0;
  /// The tree over the obstacle parts' boxes.
  std::unique_ptr<const ObstacleBroadPhase> broad_phase;
};

ObstacleBroadPhase::Box broad_box(const Box3& b) {
  return {b.centre - b.half, b.centre + b.half};
}

/// The largest distance from the body frame's origin to a point of a part posed at X_BP.
double part_radius(const Geometry& g, const Geom& geom, const Eigen::Isometry3d& X_BP) {
  if (const auto* m = std::get_if<MeshShape>(&g)) {
    double r = 0.0;
    for (const auto& v : m->mesh->vertices)
      r = std::max(r, (X_BP * v).norm());
    return r;
  }
  if (const auto* s = std::get_if<Sphere>(&g))
    return X_BP.translation().norm() + s->radius;
  // Boxes and cylinders: the corners of their local bounding box enclose them.
  const Box3 box = local_box(geom);
  double r = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    Eigen::Vector3d p = box.centre;
    for (int i = 0; i < 3; ++i)
      p[i] += (corner >> i & 1) != 0 ? box.half[i] : -box.half[i];
    r = std::max(r, (X_BP * p).norm());
  }
  return r;
}

/// The triangles of a mesh part posed at X (or, for a primitive, its box) for the pre-filter.
void add_prefilter_shape(const FclPart& part, const Eigen::Isometry3d& X,
                         std::vector<DistanceGrid::Triangle>& triangles,
                         std::vector<DistanceGrid::Box>& solids) {
  if (!part.is_mesh) {
    const Box3 box = local_box(*part.geometry).transformed(X);
    solids.push_back({box.centre - box.half, box.centre + box.half});
    return;
  }
  const auto& model = static_cast<const fcl::BVHModel<fcl::OBBRSSd>&>(*part.geometry);
  for (int i = 0; i < model.num_tris; ++i) {
    const fcl::Triangle& t = model.tri_indices[i];
    triangles.push_back(
        {X * model.vertices[t[0]], X * model.vertices[t[1]], X * model.vertices[t[2]]});
  }
}

/// Principal axes of the points (about the reference point, the origin), longest extent first.
ObjectExtent principal_extent(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points)
    scatter += p * p.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  ObjectExtent e;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = eig.eigenvectors().col(2 - k);  // largest spread first
    double half = 0.0;
    for (const auto& p : points)
      half = std::max(half, std::abs(p.dot(axis)));
    e.axes.col(k) = axis;
    e.half_extents(k) = half;
  }
  return e;
}

/// The most inner spheres a pre-filter query opens before it leaves the query to FCL.
constexpr int kPrefilterBudget = 64;

/// query_work()'s weights, in tests of a pair of boxes: a query's fixed part (its pose, the broad
/// phase), a pair of triangles, a sphere the pre-filter opens (two grid look-ups), a call to FCL.
constexpr std::uint64_t kQueryWork = 10;
constexpr std::uint64_t kTriangleWork = 4;
constexpr std::uint64_t kSphereWork = 2;
constexpr std::uint64_t kFclCallWork = 40;

/// The distance grid of the obstacles and the sphere tree of the object.
struct Prefilter {
  Bounds bounds;
  double spacing;
  DistanceGrid grid;
  SphereTree object;
  /// The workspace guide's step 1, which depends on the grid and the bounds only: built here,
  /// once per problem, so that a planner's route (on its clock) starts from it.
  GuideBlocks blocks;
};

std::shared_ptr<const Prefilter> make_prefilter(const SharedGeometry& g, const Bounds& bounds,
                                                double spacing) {
  std::vector<DistanceGrid::Triangle> triangles;
  std::vector<DistanceGrid::Box> solids;
  for (const FclPart& part : g.obstacles)
    add_prefilter_shape(part, part.pose, triangles, solids);
  // Every point of the object stays within its radius of the reference point.
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(g.object_radius);
  DistanceGrid grid({bounds.min - grow, bounds.max + grow}, spacing, triangles, solids);
  triangles.clear();
  solids.clear();
  for (const FclPart& part : g.object)
    add_prefilter_shape(part, part.pose, triangles, solids);
  SphereTree object(triangles, solids, grid.spacing());
  GuideBlocks blocks(grid, bounds);
  return std::make_shared<const Prefilter>(
      Prefilter{bounds, spacing, std::move(grid), std::move(object), std::move(blocks)});
}

/// Adds a walk's tests to the counters.
void count(const WalkTests& tests, CollisionCounters& counters) {
  counters.box_tests += tests.boxes;
  counters.triangle_tests += tests.triangles;
}

/// Whether one part of the object (at X_WP) touches one part of an obstacle: tandem's walk of the
/// OBB trees for two meshes (fcl::collide's answer), fcl::collide otherwise. An FCL exception
/// counts as a collision.
bool parts_collide(const FclPart& part, const Eigen::Isometry3d& X_WP, const FclPart& obstacle,
                   const fcl::CollisionRequestd& request, CollisionCounters& counters) {
  if (part.is_mesh && obstacle.is_mesh) {
    WalkTests tests;
    const bool hit =
        meshes_intersect(obb_tree(part), X_WP, obb_tree(obstacle), obstacle.pose, &tests);
    count(tests, counters);
    return hit;
  }
  ++counters.fcl_calls;
  try {
    fcl::CollisionResultd result;
    return fcl::collide(part.collision_geometry.get(), X_WP, obstacle.collision_geometry.get(),
                        obstacle.pose, request, result) > 0;
  } catch (const std::exception&) {
    // GJK/EPA can throw on degenerate input (fcl #395, #415): be conservative.
    ++counters.fcl_errors;
    return true;
  }
}

/// The nearest points of one part of the object (at X_WP) and one part of an obstacle, or a
/// collision (FCL's distance is not signed: touching parts have no direction). An FCL exception
/// counts as a collision.
NearestObstacle nearest_pair(const FclPart& part, const Eigen::Isometry3d& X_WP,
                             const FclPart& obstacle, const fcl::CollisionRequestd& collision,
                             const fcl::DistanceRequestd& distance, CollisionCounters& counters) {
  const NearestObstacle touching{true, 0.0, X_WP.translation(), X_WP.translation(),
                                 obstacle.obstacle};
  if (parts_collide(part, X_WP, obstacle, collision, counters))
    return touching;
  try {
    // NOTE: FCL 0.7 returns nearest points in the objects' local frames, not the world frame,
    // for a primitive passed before a mesh, and for a sphere against a mesh in either order
    // (checked for every pair of geometry kinds in collision_checker_test). So the mesh goes
    // first, and the points of a sphere-mesh pair are taken to the world frame here.
    const bool obstacle_first = obstacle.is_mesh && !part.is_mesh;
    ++counters.fcl_calls;
    fcl::DistanceResultd result;
    if (obstacle_first) {
      fcl::distance(obstacle.geometry.get(), obstacle.pose, part.geometry.get(), X_WP, distance,
                    result);
      std::swap(result.nearest_points[0], result.nearest_points[1]);
    } else {
      fcl::distance(part.geometry.get(), X_WP, obstacle.geometry.get(), obstacle.pose, distance,
                    result);
    }
    if ((obstacle.is_mesh && part.is_sphere) || (part.is_mesh && obstacle.is_sphere)) {
      result.nearest_points[0] = X_WP * result.nearest_points[0];
      result.nearest_points[1] = obstacle.pose * result.nearest_points[1];
    }
    return NearestObstacle{false, std::max(0.0, result.min_distance), result.nearest_points[0],
                           result.nearest_points[1], obstacle.obstacle};
  } catch (const std::exception&) {
    ++counters.fcl_errors;
    return touching;
  }
}

/// The pre-filter's bound on the object's clearance at X_WO up to cap, or a value below `enough`
/// when it cannot show `enough`.
double prefilter_clearance(const Prefilter& p, const Eigen::Isometry3d& X_WO, double enough,
                           double cap, CollisionCounters& counters) {
  return p.object.clearance_at(p.grid, X_WO, enough, cap, kPrefilterBudget,
                               &counters.spheres_opened);
}

}  // namespace

struct CollisionChecker::Impl {
  std::shared_ptr<const SharedGeometry> geometry;
  /// The pre-filter last built, kept while it is off (drop_distance_grid) so that switching it
  /// back on costs nothing; `active` is it when on, null when off.
  std::shared_ptr<const Prefilter> built;
  const Prefilter* active = nullptr;
  CollisionCounters counters;
  fcl::CollisionRequestd collision_request;
  fcl::DistanceRequestd distance_request;
  fcl::DistanceRequestd clearance_request;
  BroadPhase broad_phase = BroadPhase::automatic;
  std::vector<std::size_t> candidates;  ///< for_parts_within()'s, kept to spare allocations
  struct Seen {
    std::size_t object_part, obstacle_part;
    NearestObstacle pair;
  };
  std::vector<Seen> seen;  ///< nearest_through_tree()'s pairs

  explicit Impl(std::shared_ptr<const SharedGeometry> g) : geometry(std::move(g)) {
    collision_request.num_max_contacts = 1;
    collision_request.enable_contact = false;
    distance_request.enable_nearest_points = true;
    // FCL prunes a pair of bounding volumes at distance c from the best distance d found so far
    // when c >= d - abs_err and c * (1 + rel_err) >= d: with abs_err this large only the relative
    // rule is left, which makes the result a lower bound within the factor 1 + rel_err.
    clearance_request.rel_err = kClearanceRelativeError;
    clearance_request.abs_err = std::numeric_limits<double>::max();
  }

  Eigen::Isometry3d world_pose(const FclPart& part, const Eigen::Isometry3d& X_WO) const {
    return part.pose_is_identity ? X_WO : X_WO * part.pose;
  }

  /// The tree when it is in use (from `from` obstacle parts on, in automatic mode), else null.
  const ObstacleBroadPhase* tree(std::size_t from = CollisionChecker::kBroadPhaseFrom) const {
    const bool use = broad_phase == BroadPhase::tree ||
                     (broad_phase == BroadPhase::automatic && geometry->obstacles.size() >= from);
    return use ? geometry->broad_phase.get() : nullptr;
  }

  /// Calls visit(obstacle part) for the obstacle parts whose boxes overlap `box` (the linear
  /// loop's test, whichever way they are found), until a call returns true.
  template <class Visit>
  bool for_overlapping(const Box3& box, Visit&& visit) const {
    const auto& obstacles = geometry->obstacles;
    const auto test = [&](std::size_t i) { return box.overlaps(obstacles[i].box) && visit(i); };
    if (const ObstacleBroadPhase* t = tree())
      return t->overlapping(broad_box(box), test);
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      if (test(i))
        return true;
    }
    return false;
  }

  /// Calls visit(obstacle part), in the scene's order, for the obstacle parts whose boxes may be
  /// within `within` of one of `boxes` (every part without the tree; the tree's candidates with
  /// it), until a call returns true. The order keeps order-dependent answers (clearance bounds,
  /// ties) the linear loop's.
  template <class Visit>
  bool for_parts_within(const Box3* boxes, std::size_t count, double within, Visit&& visit) {
    const ObstacleBroadPhase* t = tree();
    if (t == nullptr) {
      for (std::size_t i = 0; i < geometry->obstacles.size(); ++i) {
        if (visit(i))
          return true;
      }
      return false;
    }
    candidates.clear();
    for (std::size_t k = 0; k < count; ++k) {
      Box3 box = boxes[k];
      box.half.array() += within;
      t->overlapping(broad_box(box), [&](std::size_t i) {
        candidates.push_back(i);
        return false;
      });
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (const std::size_t i : candidates) {
      if (visit(i))
        return true;
    }
    return false;
  }

  /// The nearest obstacle part to the object at X_WO: every pair of parts in turn, skipping those
  /// whose boxes are no nearer than the best so far; the first colliding pair ends it.
  NearestObstacle nearest_linear(const Eigen::Isometry3d& X_WO) {
    NearestObstacle best;
    best.distance = std::numeric_limits<double>::infinity();
    for (const auto& part : geometry->object) {
      const Eigen::Isometry3d X_WP = world_pose(part, X_WO);
      const Box3 box = part.box.transformed(X_WP);
      for (const auto& obstacle : geometry->obstacles) {
        if (box.distance_to(obstacle.box) >= best.distance)
          continue;
        const NearestObstacle pair =
            nearest_pair(part, X_WP, obstacle, collision_request, distance_request, counters);
        if (pair.in_collision)
          return pair;
        if (pair.distance < best.distance)
          best = pair;
      }
    }
    return best;
  }

  /// nearest_linear()'s answer through the tree: the least distance found nearest boxes first,
  /// then, of the pairs before the one found (in the order nearest_linear() takes them), the first
  /// as near or colliding, which is the one nearest_linear() keeps.
  NearestObstacle nearest_through_tree(const Eigen::Isometry3d& X_WO) {
    const ObstacleBroadPhase& t = *geometry->broad_phase;
    seen.clear();
    NearestObstacle best;
    best.distance = std::numeric_limits<double>::infinity();
    std::pair<std::size_t, std::size_t> key{SIZE_MAX, SIZE_MAX};  // (object part, obstacle part)
    for (std::size_t k = 0; k < geometry->object.size() && !best.in_collision; ++k) {
      const FclPart& part = geometry->object[k];
      const Eigen::Isometry3d X_WP = world_pose(part, X_WO);
      const Box3 box = part.box.transformed(X_WP);
      t.nearer_than(broad_box(box), best.distance, [&](std::size_t i, double&) {
        if (box.distance_to(geometry->obstacles[i].box) >= best.distance)
          return false;
        const NearestObstacle pair = nearest_pair(part, X_WP, geometry->obstacles[i],
                                                  collision_request, distance_request, counters);
        seen.push_back({k, i, pair});
        if (pair.in_collision || pair.distance < best.distance) {
          best = pair;
          key = {k, i};
        }
        return pair.in_collision;
      });
    }
    first_in_order(X_WO, best, key);
    return best;
  }

  /// Of the pairs before `key` whose boxes are within best's distance, the first that collides or
  /// is as near as best (ties, or the first colliding pair) replaces it.
  void first_in_order(const Eigen::Isometry3d& X_WO, NearestObstacle& best,
                      std::pair<std::size_t, std::size_t>& key) {
    for (std::size_t k = 0; k <= key.first && k < geometry->object.size(); ++k) {
      const FclPart& part = geometry->object[k];
      const Eigen::Isometry3d X_WP = world_pose(part, X_WO);
      const Box3 box = part.box.transformed(X_WP);
      const bool found = for_parts_within(&box, 1, best.distance, [&](std::size_t i) {
        if (std::pair(k, i) >= key)
          return true;
        if (box.distance_to(geometry->obstacles[i].box) > best.distance)
          return false;
        const NearestObstacle pair = pair_of(k, i, X_WP);
        if (!pair.in_collision && !(pair.distance == best.distance && !best.in_collision))
          return false;
        best = pair;
        key = {k, i};
        return true;
      });
      if (found)
        return;
    }
  }

  /// The pair's answer, from nearest_through_tree()'s if it asked FCL already.
  NearestObstacle pair_of(std::size_t k, std::size_t i, const Eigen::Isometry3d& X_WP) {
    for (const Seen& s : seen) {
      if (s.object_part == k && s.obstacle_part == i)
        return s.pair;
    }
    return nearest_pair(geometry->object[k], X_WP, geometry->obstacles[i], collision_request,
                        distance_request, counters);
  }
};

CollisionChecker::CollisionChecker(const Scene& scene) {
  auto g = std::make_shared<SharedGeometry>();
  for (const auto& part : scene.object.parts) {
    const FclModels models = make_models(part.geometry, "object '" + scene.object.name + "'");
    const bool identity = part.pose.isApprox(Eigen::Isometry3d::Identity(), 0.0);
    g->object.push_back({models.distance, models.collision, part.pose, identity,
                         is_mesh(part.geometry), is_sphere(part.geometry),
                         local_box(*models.distance), 0});
    g->object_radius =
        std::max(g->object_radius, part_radius(part.geometry, *models.distance, part.pose));
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Body& body = scene.obstacles[i];
    g->obstacle_names.push_back(body.name);
    for (const auto& part : body.parts) {
      const FclModels models = make_models(part.geometry, "obstacle '" + body.name + "'");
      const bool identity = part.pose.isApprox(Eigen::Isometry3d::Identity(), 0.0);
      g->obstacles.push_back({models.distance, models.collision, part.pose, identity,
                              is_mesh(part.geometry), is_sphere(part.geometry),
                              local_box(*models.distance).transformed(part.pose), i});
    }
  }
  if (g->object.empty())
    throw InputError("object '" + scene.object.name + "'", "the moving object has no geometry");
  std::vector<ObstacleBroadPhase::Box> boxes;
  for (const FclPart& part : g->obstacles)
    boxes.push_back(broad_box(part.box));
  g->broad_phase = std::make_unique<const ObstacleBroadPhase>(boxes);
  impl_ = std::make_unique<Impl>(std::move(g));
}

CollisionChecker::CollisionChecker(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CollisionChecker::~CollisionChecker() = default;
CollisionChecker::CollisionChecker(CollisionChecker&&) noexcept = default;
CollisionChecker& CollisionChecker::operator=(CollisionChecker&&) noexcept = default;

CollisionChecker CollisionChecker::clone() const {
  auto impl = std::make_unique<Impl>(impl_->geometry);
  impl->built = impl_->built;
  impl->active = impl_->active;
  impl->broad_phase = impl_->broad_phase;
  return CollisionChecker(std::move(impl));
}

void CollisionChecker::use_distance_grid(const Bounds& bounds, double spacing) {
  if (!bounds.is_valid() || !(spacing > 0.0) || !std::isfinite(spacing))
    throw InputError("distance grid", "needs valid bounds and a positive spacing");
  const auto& p = impl_->built;
  if (p == nullptr || p->spacing != spacing || p->bounds.min != bounds.min ||
      p->bounds.max != bounds.max) {
    impl_->built = make_prefilter(*impl_->geometry, bounds, spacing);
  }
  impl_->active = impl_->built.get();
}

void CollisionChecker::drop_distance_grid() {
  impl_->active = nullptr;
}

bool CollisionChecker::has_distance_grid() const {
  return impl_->active != nullptr;
}

const DistanceGrid* CollisionChecker::distance_grid() const {
  return impl_->active != nullptr ? &impl_->active->grid : nullptr;
}

const GuideBlocks* CollisionChecker::guide_blocks() const {
  return impl_->active != nullptr ? &impl_->active->blocks : nullptr;
}

ObjectExtent CollisionChecker::object_extent() const {
  std::vector<DistanceGrid::Triangle> triangles;
  std::vector<DistanceGrid::Box> solids;
  for (const FclPart& part : impl_->geometry->object)
    add_prefilter_shape(part, part.pose, triangles, solids);
  std::vector<Eigen::Vector3d> points;
  for (const auto& t : triangles)
    points.insert(points.end(), {t.a, t.b, t.c});
  for (const auto& b : solids) {
    for (int corner = 0; corner < 8; ++corner)
      points.push_back({(corner & 1) != 0 ? b.max.x() : b.min.x(),
                        (corner & 2) != 0 ? b.max.y() : b.min.y(),
                        (corner & 4) != 0 ? b.max.z() : b.min.z()});
  }
  return principal_extent(points);
}

bool CollisionChecker::is_collision_free(const Config& q) {
  Impl& m = *impl_;
  ++m.counters.state_checks;
  const Eigen::Isometry3d X_WO = q.pose();
  if (m.active != nullptr) {
    // Any positive bound shows that nothing touches.
    const double positive = 1e-6 * m.active->grid.spacing();
    if (prefilter_clearance(*m.active, X_WO, positive, positive, m.counters) >= positive) {
      ++m.counters.prefilter_answers;
      return true;
    }
  }
  for (const auto& part : m.geometry->object) {
    const Eigen::Isometry3d X_WP = m.world_pose(part, X_WO);
    const bool hit = m.for_overlapping(part.box.transformed(X_WP), [&](std::size_t i) {
      return parts_collide(part, X_WP, m.geometry->obstacles[i], m.collision_request, m.counters);
    });
    if (hit)
      return false;
  }
  return true;
}

NearestObstacle CollisionChecker::nearest_obstacle(const Config& q) {
  Impl& m = *impl_;
  ++m.counters.distance_queries;
  const Eigen::Isometry3d X_WO = q.pose();
  return m.tree(kNearestThroughTreeFrom) != nullptr ? m.nearest_through_tree(X_WO)
                                                    : m.nearest_linear(X_WO);
}

std::vector<NearestObstacle> CollisionChecker::nearest_surfaces(const Config& q, double within) {
  Impl& m = *impl_;
  ++m.counters.distance_queries;
  std::vector<NearestObstacle> out;
  const Eigen::Isometry3d X_WO = q.pose();
  std::vector<Box3> boxes;
  for (const auto& part : m.geometry->object)
    boxes.push_back(part.box.transformed(m.world_pose(part, X_WO)));
  const bool touching = m.for_parts_within(boxes.data(), boxes.size(), within, [&](std::size_t i) {
    const FclPart& obstacle = m.geometry->obstacles[i];
    NearestObstacle best;
    best.distance = within;
    bool found = false;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (boxes[k].distance_to(obstacle.box) > best.distance)
        continue;
      const FclPart& part = m.geometry->object[k];
      const NearestObstacle pair =
          nearest_pair(part, m.world_pose(part, X_WO), obstacle, m.collision_request,
                       m.distance_request, m.counters);
      if (pair.in_collision)
        return true;
      if (pair.distance <= best.distance) {
        best = pair;
        found = true;
      }
    }
    if (found)
      out.push_back(best);
    return false;
  });
  if (touching)
    return {};
  std::stable_sort(out.begin(), out.end(), [](const NearestObstacle& a, const NearestObstacle& b) {
    return a.distance < b.distance;
  });
  return out;
}

double CollisionChecker::clearance_bound(const Config& q, double cap, double fcl_cap) {
  Impl& m = *impl_;
  ++m.counters.clearance_queries;
  constexpr double kGrow = 1.0 + kClearanceRelativeError;
  const Eigen::Isometry3d X_WO = q.pose();
  fcl_cap = std::min(fcl_cap, cap);
  if (m.active != nullptr) {
    const double c = prefilter_clearance(*m.active, X_WO, fcl_cap, cap, m.counters);
    if (c >= fcl_cap) {
      ++m.counters.prefilter_answers;
      return c;
    }
  }
  double best = fcl_cap;
  bool failed = false;
  for (const auto& part : m.geometry->object) {
    const Eigen::Isometry3d X_WP = m.world_pose(part, X_WO);
    // The candidates in the scene's order: the bound depends on the order FCL meets the parts in.
    const Box3 box = part.box.transformed(X_WP);
    const bool stop = m.for_parts_within(&box, 1, fcl_cap, [&](std::size_t i) {
      const FclPart& obstacle = m.geometry->obstacles[i];
      if (box.distance_to(obstacle.box) >= best)
        return false;
      if (part.is_mesh && obstacle.is_mesh) {
        WalkTests tests;
        best = mesh_distance_bound(obb_tree(part), X_WP, obb_tree(obstacle), obstacle.pose, best,
                                   kClearanceRelativeError, &tests);
        count(tests, m.counters);
        return best <= 0.0;
      }
      // Starting from best * (1 + e), FCL prunes every pair of bounding volumes at least that far
      // apart; what it returns, d, bounds the true distance from below as d / (1 + e). If it
      // found nothing closer, d is that start, and best stays: best * (1 + e) / (1 + e) may round
      // below best, and a state as far as the cap would then read as closer than it.
      const double start = best * kGrow;
      fcl::DistanceResultd result(start);
      ++m.counters.fcl_calls;
      try {
        fcl::distance(part.geometry.get(), X_WP, obstacle.geometry.get(), obstacle.pose,
                      m.clearance_request, result);
      } catch (const std::exception&) {
        ++m.counters.fcl_errors;
        failed = true;
        return true;
      }
      if (result.min_distance < start)
        best = std::min(best, result.min_distance / kGrow);
      return best <= 0.0;
    });
    if (failed)
      return 0.0;
    if (stop)
      return best;
  }
  return best;
}

double CollisionChecker::object_radius() const {
  return impl_->geometry->object_radius;
}

void CollisionChecker::use_broad_phase(BroadPhase broad_phase) {
  impl_->broad_phase = broad_phase;
}

bool CollisionChecker::uses_tree() const {
  return impl_->tree() != nullptr;
}

std::size_t CollisionChecker::obstacle_count() const {
  return impl_->geometry->obstacle_names.size();
}

const std::string& CollisionChecker::obstacle_name(std::size_t index) const {
  return impl_->geometry->obstacle_names.at(index);
}

std::uint64_t query_work(const CollisionCounters& c) {
  const std::uint64_t queries = c.state_checks + c.distance_queries + c.clearance_queries;
  return kQueryWork * queries + c.box_tests + kTriangleWork * c.triangle_tests +
         kSphereWork * c.spheres_opened + kFclCallWork * c.fcl_calls;
}

const CollisionCounters& CollisionChecker::counters() const {
  return impl_->counters;
}
void CollisionChecker::reset_counters() {
  impl_->counters = {};
}

void CollisionChecker::add_counters(const CollisionCounters& other) {
  CollisionCounters& c = impl_->counters;
  c.state_checks += other.state_checks;
  c.distance_queries += other.distance_queries;
  c.clearance_queries += other.clearance_queries;
  c.fcl_errors += other.fcl_errors;
  c.prefilter_answers += other.prefilter_answers;
  c.box_tests += other.box_tests;
  c.triangle_tests += other.triangle_tests;
  c.spheres_opened += other.spheres_opened;
  c.fcl_calls += other.fcl_calls;
}

}  // namespace tandem

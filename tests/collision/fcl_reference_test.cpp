// tandem's yes/no collision query held against FCL as OMPL.app and FCL's own examples use it: one
// BVHModel<OBBRSS> per mesh, FCL primitives, fcl::collide with a default request. tandem answers
// with OBB trees (faster for yes/no), walked by its own code between two meshes
// (mesh_proximity.hpp), after the distance-grid pre-filter; none of these may ever change an
// answer. On uniform samples and on configurations a hair either side of contact, of every shipped
// problem.

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "tandem/collision/collision_checker.hpp"
#include "tandem/core/rng.hpp"
#include "tandem/scene/problem_loader.hpp"

namespace tandem {
namespace {

using Geom = fcl::CollisionGeometryd;

std::shared_ptr<Geom> reference_geometry(const Geometry& g) {
  if (const auto* b = std::get_if<Box>(&g))
    return std::make_shared<fcl::Boxd>(b->size);
  if (const auto* s = std::get_if<Sphere>(&g))
    return std::make_shared<fcl::Sphered>(s->radius);
  if (const auto* c = std::get_if<Cylinder>(&g))
    return std::make_shared<fcl::Cylinderd>(c->radius, c->length);
  const TriangleMesh& mesh = *std::get<MeshShape>(g).mesh;
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Triangle> tris;
  for (const auto& t : mesh.triangles)
    tris.emplace_back(t[0], t[1], t[2]);
  model->beginModel();
  model->addSubModel(mesh.vertices, tris);
  model->endModel();
  return model;
}

struct ReferencePart {
  std::shared_ptr<Geom> geometry;
  Eigen::Isometry3d pose;
};

std::vector<ReferencePart> reference_parts(const std::vector<Part>& parts) {
  std::vector<ReferencePart> out;
  for (const Part& p : parts)
    out.push_back({reference_geometry(p.geometry), p.pose});
  return out;
}

/// FCL's answer: does any part of the object at q touch any obstacle part?
bool reference_collides(const std::vector<ReferencePart>& object,
                        const std::vector<ReferencePart>& obstacles, const Config& q) {
  const Eigen::Isometry3d X_WO = q.pose();
  for (const ReferencePart& o : object) {
    for (const ReferencePart& e : obstacles) {
      fcl::CollisionRequestd request;
      fcl::CollisionResultd result;
      if (fcl::collide(o.geometry.get(), X_WO * o.pose, e.geometry.get(), e.pose, request, result) >
          0)
        return true;
    }
  }
  return false;
}

TEST(FclReference, YesNoAnswersAreFclsOnEveryShippedProblem) {
  std::size_t near_contact = 0, grid_answers = 0;
  for (const std::string& name : test::shipped_problems()) {
    SCOPED_TRACE(name);
    const Problem p = load_problem(name);
    const std::vector<ReferencePart> object = reference_parts(p.scene.object.parts);
    std::vector<ReferencePart> obstacles;
    for (const Body& body : p.scene.obstacles) {
      for (const Part& part : body.parts) {
        for (ReferencePart r : reference_parts({part}))
          obstacles.push_back(r);
      }
    }
    CollisionChecker plain(p.scene);
    CollisionChecker gridded(p.scene);
    gridded.use_distance_grid(p.space.bounds(), 0.5 * p.space.translation_step());

    std::vector<Config> configs = test::near_contact_configs(p, 17, 60);
    near_contact += configs.size();
    Rng rng(19);
    for (int i = 0; i < 300; ++i)
      configs.push_back(p.space.sample_uniform(rng));
    int free = 0, colliding = 0;
    for (const Config& q : configs) {
      const bool expected_free = !reference_collides(object, obstacles, q);
      ASSERT_EQ(plain.is_collision_free(q), expected_free);
      ASSERT_EQ(gridded.is_collision_free(q), expected_free);
      (expected_free ? free : colliding) += 1;
    }
    EXPECT_GT(free, 0);
    EXPECT_GT(colliding, 0);
    grid_answers += gridded.counters().prefilter_answers;
  }
  // The hard cases were there: configurations a hair either side of contact.
  EXPECT_GE(near_contact, 4u * 2u * 60u);
  EXPECT_GT(grid_answers, 0u);
}

}  // namespace
}  // namespace tandem

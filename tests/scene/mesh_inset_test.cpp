#include "tandem/scene/mesh_inset.hpp"

#include <fcl/fcl.h>
#include <gtest/gtest.h>

#include "support/cad_assembly.hpp"
#include "support/test_support.hpp"
#include "tandem/scene/cad_loader.hpp"
#include "tandem/scene/geometry.hpp"

namespace tandem {
namespace {

/// FCL's distance between two meshes as triangle soups (surfaces).
double surface_distance(const TriangleMesh& a, const TriangleMesh& b) {
  auto model = [](const TriangleMesh& m) {
    auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    std::vector<fcl::Triangle> tris;
    for (const auto& t : m.triangles)
      tris.emplace_back(t[0], t[1], t[2]);
    bvh->beginModel();
    bvh->addSubModel(m.vertices, tris);
    bvh->endModel();
    return bvh;
  };
  fcl::CollisionObjectd oa(model(a)), ob(model(b));
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  fcl::distance(&oa, &ob, request, result);
  return result.min_distance;
}

TEST(MeshInset, ABoxShrinksByTheDistanceOnEverySide) {
  const TriangleMesh box = tessellate(Box{Eigen::Vector3d(2.0, 1.0, 0.5)});
  const TriangleMesh inset = inset_mesh(box, 0.1);
  const auto [lo, hi] = inset.bounding_box();
  EXPECT_NEAR((lo - Eigen::Vector3d(-0.9, -0.4, -0.15)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((hi - Eigen::Vector3d(0.9, 0.4, 0.15)).norm(), 0.0, 1e-12);
  EXPECT_EQ(inset.triangle_count(), box.triangle_count());
}

TEST(MeshInset, EveryFaceOfCadPartsMovesInwardByTheDistance) {
  const test::TempDir dir;
  test::write_housing(dir.path() / "housing.step");
  const CadAssembly housing = load_cad(dir.path() / "housing.step");
  // The peg (a tessellated cylinder) and the block (concave: a pocket cut in it).
  for (const char* name : {"peg", "base"}) {
    const TriangleMesh& part = housing.part(name, "test").mesh;
    for (double d : {1e-4, 5e-4}) {
      const TriangleMesh inset = inset_mesh(part, d);
      // Flat faces move by d exactly; near edges and corners the surfaces are farther apart.
      EXPECT_NEAR(surface_distance(inset, part), d, 1e-3 * d) << name << " by " << d;
      // And the inset part lies inside the part: its bounding box within by at least d.
      const auto [lo, hi] = part.bounding_box();
      const auto [ilo, ihi] = inset.bounding_box();
      EXPECT_GE((ilo - lo).minCoeff(), d * (1 - 1e-6)) << name;
      EXPECT_GE((hi - ihi).minCoeff(), d * (1 - 1e-6)) << name;
    }
  }
}

TEST(MeshInset, RejectsADistanceThatIsNotPositive) {
  const TriangleMesh box = tessellate(Box{Eigen::Vector3d(1, 1, 1)});
  EXPECT_THROW(inset_mesh(box, 0.0), std::invalid_argument);
  EXPECT_THROW(inset_mesh(box, -1.0), std::invalid_argument);
  EXPECT_THROW(inset_mesh(box, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace tandem

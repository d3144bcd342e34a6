// Triangle meshes: what sanitizing refuses.

#include "tandem/scene/mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using ::testing::HasSubstr;

TEST(SanitizeMesh, RejectsOutOfRangeIndicesAndNonFiniteVertices) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 3}};
  EXPECT_THAT(test::error_message<InputError>([&] { return sanitize_mesh(m, "m"); }),
              HasSubstr("m: triangle 0 refers to vertex 3 but the mesh has 3 vertices"));
  m.triangles = {{0, 1, 2}};
  m.vertices[1].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(test::error_message<InputError>([&] { return sanitize_mesh(m, "m"); }),
              HasSubstr("m: vertex 1 has a non-finite coordinate"));
}

}  // namespace
}  // namespace tandem

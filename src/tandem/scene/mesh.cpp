#include "tandem/scene/mesh.hpp"

#include <Eigen/Geometry>
#include <limits>

#include "tandem/core/error.hpp"

namespace tandem {

std::pair<Eigen::Vector3d, Eigen::Vector3d> TriangleMesh::bounding_box() const {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const auto& v : vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return {lo, hi};
}

std::size_t sanitize_mesh(TriangleMesh& mesh, const std::string& source) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!mesh.vertices[i].allFinite()) {
      throw InputError(source, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  const auto n = mesh.vertices.size();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& tri = mesh.triangles[i];
    for (auto index : tri) {
      if (index >= n) {
        throw InputError(source, "triangle " + std::to_string(i) + " refers to vertex " +
                                     std::to_string(index) + " but the mesh has " +
                                     std::to_string(n) + " vertices");
      }
    }
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    const double longest2 =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double twice_area = (b - a).cross(c - a).norm();
    // Relative test: the triangle's height over its longest edge is below 1e-9 of that edge.
    if (longest2 == 0.0 || twice_area <= 1e-9 * longest2)
      continue;
    mesh.triangles[kept++] = tri;
  }
  const std::size_t removed = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  if (mesh.triangles.empty()) {
    throw InputError(source, removed == 0 ? "the mesh has no triangles"
                                          : "the mesh has no triangles of non-zero area (" +
                                                std::to_string(removed) + " degenerate ones)");
  }
  return removed;
}

}  // namespace tandem

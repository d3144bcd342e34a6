#pragma once
// An indexed triangle mesh in its own frame, and the checks every mesh passes before it reaches
// FCL.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tandem {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;

  std::size_t triangle_count() const { return triangles.size(); }
  /// Componentwise bounding box of the vertices; {+inf, -inf} for an empty mesh.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> bounding_box() const;
};

/// Validates a mesh read from `source` (a file name, for messages) and removes degenerate triangles
/// (zero area: repeated or colinear vertices), which FCL's GJK/EPA cannot handle (fcl #395, #415).
/// Throws InputError when a vertex is not finite, an index is out of range, or no triangle is left.
/// Returns the number of triangles removed.
std::size_t sanitize_mesh(TriangleMesh& mesh, const std::string& source);

}  // namespace tandem

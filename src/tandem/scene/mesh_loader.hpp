#pragma once
// Reading triangle meshes from files with assimp.
//
// Only the formats tandem needs are accepted (COLLADA .dae, STL, Wavefront OBJ, PLY): assimp has a
// steady flow of importer bugs, so every other importer stays out of reach of user files.
//
// The post-processing mirrors OMPL.app's (GenNormals | Triangulate | JoinIdenticalVertices |
// SortByPType | OptimizeGraph), plus assimp's own data validation. Node transforms are applied,
// accumulated from the root, so the vertices are in the file's scene frame as OMPL.app sees it (for
// COLLADA files that declare Z_UP, assimp's root node turns the scene Y-up: (x, y, z) -> (x, z,
// -y)). No unit scaling.

#include <filesystem>

#include "tandem/scene/mesh.hpp"

namespace tandem {

struct LoadedMesh {
  TriangleMesh mesh;
  /// Mean of all mesh vertices (after post-processing and node transforms), as OMPL.app computes
  /// the robot's centre (in single precision, as OMPL.app does); taken before degenerate triangles
  /// are removed. Vertices are assimp's single-precision values, widened to double.
  Eigen::Vector3d vertex_mean = Eigen::Vector3d::Zero();
  std::size_t degenerate_removed = 0;
};

/// Throws InputError naming the file for a missing file, an unsupported format, a file assimp
/// cannot parse, or a mesh without valid triangles.
LoadedMesh load_mesh(const std::filesystem::path& file);

/// True for the file extensions load_mesh accepts.
bool is_supported_mesh_file(const std::filesystem::path& file);

}  // namespace tandem

#include "tandem/scene/mesh_loader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cctype>
#include <fstream>

#include "tandem/core/error.hpp"
#include "tandem/core/text.hpp"
#include "tandem/scene/collada_lists.hpp"
#include "tandem/scene/ply_header.hpp"

namespace tandem {
namespace {

// The vertex sum is accumulated in single precision, in the order OMPL.app visits the vertices, so
// the centre matches OMPL.app's to the bit.
void collect(const aiScene* scene, const aiNode* node, aiMatrix4x4 transform, TriangleMesh& out,
             aiVector3D& vertex_sum, std::size_t& vertex_count) {
  transform *= node->mTransformation;
  for (unsigned m = 0; m < node->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[m]];
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D p = transform * mesh->mVertices[v];
      const Eigen::Vector3d q(static_cast<double>(p.x), static_cast<double>(p.y),
                              static_cast<double>(p.z));
      out.vertices.push_back(q);
      vertex_sum += p;
    }
    vertex_count += mesh->mNumVertices;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3)
        continue;  // points and lines, split off by SortByPType
      out.triangles.push_back(
          {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) {
    collect(scene, node->mChildren[c], transform, out, vertex_sum, vertex_count);
  }
}

/// Throws InputError unless every face names 1 to N existing vertices and its mesh declares the
/// face's primitive type: assimp 5.2's triangulation aborts the process on a mesh that does not
/// (a malformed PLY face list, found by fuzzing).
void check_faces(const aiScene* scene, const std::string& name) {
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      const unsigned n = face.mNumIndices;
      const unsigned type = n == 1   ? aiPrimitiveType_POINT
                            : n == 2 ? aiPrimitiveType_LINE
                            : n == 3 ? aiPrimitiveType_TRIANGLE
                                     : aiPrimitiveType_POLYGON;
      if (n == 0 || (mesh->mPrimitiveTypes & type) == 0)
        throw InputError(name, "malformed mesh: face " + std::to_string(f) + " of mesh " +
                                   std::to_string(m) + " has " + std::to_string(n) + " vertices");
      for (unsigned k = 0; k < n; ++k) {
        if (face.mIndices[k] >= mesh->mNumVertices)
          throw InputError(name, "malformed mesh: face " + std::to_string(f) + " of mesh " +
                                     std::to_string(m) + " names a vertex it does not have");
      }
    }
  }
}

}  // namespace

bool is_supported_mesh_file(const std::filesystem::path& file) {
  static const std::array<std::string, 4> kExtensions = {".dae", ".stl", ".obj", ".ply"};
  const std::string ext = lower_extension(file);
  return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

LoadedMesh load_mesh(const std::filesystem::path& file) {
  const std::string name = file.string();
  check_file_name(name);
  if (!is_supported_mesh_file(file)) {
    throw InputError(name, "unsupported mesh format '" + file.extension().string() +
                               "' (tandem reads .dae, .stl, .obj and .ply)");
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(name,
                     std::filesystem::exists(file, ec) ? "not a regular file" : "no such file");
  }
  if (!std::ifstream(file).good())
    throw InputError(name, "cannot be opened for reading");
  if (lower_extension(file) == ".ply")
    check_ply_header(file);
  if (lower_extension(file) == ".dae")
    check_collada_lists(file);

  Assimp::Importer importer;
  // Keep points and lines out of the triangle data rather than failing on them.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, 0);
  // Read and validated first, then the faces checked, then processed (as one ReadFile with all
  // the flags would, in the same order).
  const aiScene* scene = importer.ReadFile(name, aiProcess_ValidateDataStructure);
  if (scene != nullptr) {
    check_faces(scene, name);
    scene = importer.ApplyPostProcessing(aiProcess_GenNormals | aiProcess_Triangulate |
                                         aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                         aiProcess_OptimizeGraph);
  }
  if (scene == nullptr) {
    std::string why = importer.GetErrorString();
    if (why.empty())
      why = "unknown error";
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw InputError(name, "cannot read mesh: " + why);
  }
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mRootNode == nullptr) {
    throw InputError(name, "the file holds no complete mesh scene");
  }
  LoadedMesh out;
  aiVector3D sum(0.0f, 0.0f, 0.0f);
  std::size_t count = 0;
  collect(scene, scene->mRootNode, aiMatrix4x4(), out.mesh, sum, count);
  if (count == 0 || out.mesh.triangles.empty())
    throw InputError(name, "the mesh has no triangles");
  sum /= static_cast<float>(count);
  out.vertex_mean = Eigen::Vector3d(static_cast<double>(sum.x), static_cast<double>(sum.y),
                                    static_cast<double>(sum.z));
  out.degenerate_removed = sanitize_mesh(out.mesh, name);
  return out;
}

}  // namespace tandem

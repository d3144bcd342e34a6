#pragma once
// URDF files (urdfdom) as bodies: every link's collision geometry (or, for a link without any, its
// visual geometry), posed by the joint tree at the zero configuration.
//
// Geometry: box, cylinder, sphere, and meshes (STL, OBJ, DAE, PLY via assimp) with their scale.
// Mesh file names are resolved with resolve_reference() against the URDF's folder.

#include <filesystem>

#include "tandem/scene/file_refs.hpp"
#include "tandem/scene/geometry.hpp"

namespace tandem {

enum class UrdfRole {
  object,    ///< the moving part: every joint must be fixed (tandem plans rigid parts)
  obstacle,  ///< part of the environment: movable joints are taken at their zero position
};

/// The body's parts are posed in the URDF root link's frame. Throws InputError naming the file for
/// a missing or malformed file, a non-positive or non-finite size or scale, an unusable mesh, joints
/// that form a loop (urdfdom accepts them), or (for an object) a movable joint.
Body load_urdf(const std::filesystem::path& file, UrdfRole role, const FileAccess& access);

}  // namespace tandem

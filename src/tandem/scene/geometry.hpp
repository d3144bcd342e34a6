#pragma once
// The shapes a body is made of: primitives (as URDF defines them) and triangle meshes.
//
// Frames: a Part's pose is X_BP, the part in its body's frame B. For an obstacle, B is the world
// frame; for the moving object, B is the object frame whose pose is the configuration.

#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tandem/scene/mesh.hpp"

namespace tandem {

struct Box {
  Eigen::Vector3d size;  ///< full side lengths along the part's x, y, z, > 0
};
struct Sphere {
  double radius;  ///< > 0
};
struct Cylinder {
  double radius;  ///< > 0
  double length;  ///< > 0, along the part's z axis, centred on its origin (URDF convention)
};
struct MeshShape {
  std::shared_ptr<const TriangleMesh> mesh;  ///< shared, immutable
  std::string source;                        ///< file it came from, for messages
};

using Geometry = std::variant<Box, Sphere, Cylinder, MeshShape>;

struct Part {
  Geometry geometry;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< X_BP
};

/// RGBA in [0, 1].
struct Color {
  double r = 0.7, g = 0.7, b = 0.7, a = 1.0;
};

struct Body {
  std::string name;
  std::vector<Part> parts;
  Color color;
};

/// A triangle mesh of a geometry in the part frame (primitives are tessellated; for display only,
/// not for collision, which uses the exact primitives). `segments` is the number of facets around a
/// circle.
TriangleMesh tessellate(const Geometry& geometry, int segments = 24);

/// A body's parts tessellated (as tessellate() does) into one mesh in the body's frame, each part
/// posed by its X_BP.
TriangleMesh body_mesh(const Body& body, int segments = 24);

/// Name of the geometry's kind ("box", "sphere", "cylinder", "mesh").
const char* geometry_kind(const Geometry& geometry);

}  // namespace tandem

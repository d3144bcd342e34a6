#include "tandem/scene/cad_scene.hpp"

#include <memory>

namespace tandem {
namespace {

Body body(const CadNode& node, const std::string& file, const Eigen::Isometry3d& pose) {
  Body b;
  b.name = node.path;
  b.parts.push_back(
      {MeshShape{std::make_shared<const TriangleMesh>(node.mesh), file + " (" + node.path + ")"},
       pose});
  if (node.has_color)
    b.color = node.color;
  return b;
}

}  // namespace

CadScene cad_scene(const CadAssembly& assembly, const std::string& part, const std::string& file,
                   const std::string& source) {
  CadScene scene;
  const CadNode* moving = part.empty() ? nullptr : &assembly.part(part, source);
  for (const CadNode& node : assembly.nodes) {
    if (node.assembly || node.mesh.triangles.empty())
      continue;
    if (&node == moving) {
      scene.object = body(node, file, Eigen::Isometry3d::Identity());
      Config seat;
      seat.t = node.placement.translation();
      seat.q = Eigen::Quaterniond(node.placement.linear()).normalized();
      scene.seat = seat;
    } else {
      scene.obstacles.push_back(body(node, file, node.placement));
    }
  }
  return scene;
}

}  // namespace tandem

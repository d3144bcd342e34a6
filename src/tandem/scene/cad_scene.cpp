#include "tandem/scene/cad_scene.hpp"

#include <memory>

#include "tandem/scene/mesh_inset.hpp"

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

double default_seat_tolerance(const CadAssembly& assembly) {
  return 2.0 * assembly.linear_deflection;
}

CadScene cad_scene(const CadAssembly& assembly, const std::string& part, const std::string& file,
                   const std::string& source, double seat_tolerance) {
  CadScene scene;
  const CadNode* moving = part.empty() ? nullptr : &assembly.part(part, source);
  for (const CadNode& node : assembly.nodes) {
    if (node.assembly || node.mesh.triangles.empty())
      continue;
    if (&node != moving) {
      scene.obstacles.push_back(body(node, file, node.placement));
      continue;
    }
    CadNode object = node;
    const auto [lo, hi] = node.mesh.bounding_box();
    scene.centre = (lo + hi) / 2.0;
    for (auto& v : object.mesh.vertices)
      v -= scene.centre;
    if (seat_tolerance > 0.0)
      object.mesh = inset_mesh(object.mesh, seat_tolerance);
    scene.seat_tolerance = seat_tolerance;
    scene.object = body(object, file, Eigen::Isometry3d::Identity());
    const Eigen::Isometry3d seat = node.placement * Eigen::Translation3d(scene.centre);
    scene.seat = Config{seat.translation(), Eigen::Quaterniond(seat.linear()).normalized()};
  }
  return scene;
}

}  // namespace tandem

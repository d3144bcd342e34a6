#include "tandem/scene/mesh_inset.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <stdexcept>

namespace tandem {
namespace {

/// The mesh with vertices at the same position (to 1e-9 of its size) merged.
TriangleMesh welded(const TriangleMesh& mesh) {
  const auto [lo, hi] = mesh.bounding_box();
  const double cell = 1e-9 * std::max((hi - lo).norm(), 1e-300);
  std::map<std::array<long long, 3>, std::uint32_t> index;
  std::vector<std::uint32_t> remap(mesh.vertices.size());
  TriangleMesh out;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3d k = ((mesh.vertices[i] - lo) / cell).array().round();
    const std::array<long long, 3> key{static_cast<long long>(k.x()), static_cast<long long>(k.y()),
                                       static_cast<long long>(k.z())};
    const auto [it, added] = index.emplace(key, static_cast<std::uint32_t>(out.vertices.size()));
    if (added)
      out.vertices.push_back(mesh.vertices[i]);
    remap[i] = it->second;
  }
  for (const auto& t : mesh.triangles)
    out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  return out;
}

/// The displacement d of a vertex such that n_f . d = -distance for each of its faces' unit
/// normals n_f (the distinct ones), by least squares.
Eigen::Vector3d displacement(const std::vector<Eigen::Vector3d>& normals, double distance) {
  std::vector<Eigen::Vector3d> distinct;
  for (const auto& n : normals) {
    bool seen = false;
    for (const auto& m : distinct)
      seen = seen || n.dot(m) > 1.0 - 1e-9;
    if (!seen)
      distinct.push_back(n);
  }
  Eigen::MatrixXd A(static_cast<Eigen::Index>(distinct.size()), 3);
  for (std::size_t k = 0; k < distinct.size(); ++k)
    A.row(static_cast<Eigen::Index>(k)) = distinct[k].transpose();
  const Eigen::VectorXd b = Eigen::VectorXd::Constant(A.rows(), -distance);
  // The minimum-norm solution: along the normal for one plane, on the planes' line for two.
  // Directions the normals barely span (nearly parallel faces of a curved surface) are dropped.
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A.cols(), A.cols());
  cod.setThreshold(1e-6);
  cod.compute(A);
  const Eigen::Vector3d d = cod.solve(b);
  if (d.norm() <= 4.0 * distance)
    return d;
  // A cone of faces sharper than the planes' meeting point can follow: along their mean normal,
  // far enough that every face moves by the distance (at most four times it).
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& n : distinct)
    mean += n;
  mean.normalize();
  double least = 1.0;
  for (const auto& n : distinct)
    least = std::min(least, n.dot(mean));
  return -distance * mean / std::max(least, 0.25);
}

}  // namespace

TriangleMesh inset_mesh(const TriangleMesh& mesh, double distance) {
  if (!(distance > 0.0) || !std::isfinite(distance))
    throw std::invalid_argument("inset_mesh: the distance must be positive and finite");
  TriangleMesh out = welded(mesh);
  std::vector<std::vector<Eigen::Vector3d>> normals(out.vertices.size());
  for (const auto& t : out.triangles) {
    const Eigen::Vector3d n =
        (out.vertices[t[1]] - out.vertices[t[0]]).cross(out.vertices[t[2]] - out.vertices[t[0]]);
    if (n.norm() == 0.0)
      continue;
    for (auto v : t)
      normals[v].push_back(n.normalized());
  }
  for (std::size_t v = 0; v < out.vertices.size(); ++v) {
    if (!normals[v].empty())
      out.vertices[v] += displacement(normals[v], distance);
  }
  return out;
}

}  // namespace tandem

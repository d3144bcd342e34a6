#include "tandem/export/motion_envelope.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

/// Facets around a circle when a curved primitive is tessellated for the envelope.
constexpr int kSegments = 96;
/// At most this many poses, and this many voxels along an axis of the swept box.
constexpr std::size_t kMaxPoses = 20000;
constexpr double kMaxVoxelsAcross = 4096;

/// How far inside a primitive its tessellation (tessellate, in scene/geometry) may lie: the
/// sagitta of a facet. A cylinder's facets span 2 pi / n of its circle; a sphere's quads span
/// 2 pi / n in latitude and longitude, so their corners are within sqrt(2) pi / n of their middle.
double tessellation_gap(const Geometry& g) {
  const double n = kSegments;
  if (const auto* c = std::get_if<Cylinder>(&g))
    return c->radius * (1.0 - std::cos(std::numbers::pi / n));
  if (const auto* s = std::get_if<Sphere>(&g))
    return s->radius * (1.0 - std::cos(std::numbers::sqrt2 * std::numbers::pi / n));
  return 0.0;
}

/// The object's parts as one mesh in the object frame, with its radius (the largest distance of a
/// point of the true geometry from the object frame's origin) and the largest tessellation gap.
struct ObjectMesh {
  TriangleMesh mesh;
  double radius = 0.0;
  double gap = 0.0;
};

ObjectMesh object_mesh(const Body& object) {
  ObjectMesh out{body_mesh(object, kSegments)};
  for (const Part& part : object.parts)
    out.gap = std::max(out.gap, tessellation_gap(part.geometry));
  for (const Eigen::Vector3d& v : out.mesh.vertices)
    out.radius = std::max(out.radius, v.norm());
  out.radius += out.gap;
  return out;
}

/// Poses along the path, no point of the part moving more than `step` between two neighbours: at
/// equal shares of the path's displacement bound (|dt| + angle x radius, summed over the motions),
/// so a path of many short motions needs no more poses than one long motion.
std::vector<Config> rasterised_poses(const Path& path, const SE3Space& space, double radius,
                                     double step) {
  std::vector<double> along{0.0};  // the displacement bound from the start to each state
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Config &a = path[i - 1], &b = path[i];
    along.push_back(along.back() + (b.t - a.t).norm() +
                    SE3Space::rotation_angle(a.q, b.q) * radius);
  }
  const double pieces = std::ceil(along.back() / step);
  if (pieces + 1 > static_cast<double>(kMaxPoses))
    throw InputError("--voxel", "too small for this path: the envelope would need more than " +
                                    std::to_string(kMaxPoses) + " poses of the part");
  const auto n = static_cast<std::size_t>(pieces);
  std::vector<Config> poses{path.front()};
  std::size_t i = 1;
  for (std::size_t k = 1; k <= n; ++k) {
    const double at = along.back() * static_cast<double>(k) / static_cast<double>(n);
    while (i + 1 < path.size() && along[i] < at)
      ++i;
    const double length = along[i] - along[i - 1];
    const double s = length > 0 ? std::clamp((at - along[i - 1]) / length, 0.0, 1.0) : 1.0;
    poses.push_back(space.interpolate(path[i - 1], path[i], s));
  }
  return poses;
}

void check_extent(const std::vector<Config>& poses, double radius, double voxel) {
  Eigen::Vector3d lo = poses.front().t, hi = lo;
  for (const Config& q : poses) {
    lo = lo.cwiseMin(q.t);
    hi = hi.cwiseMax(q.t);
  }
  if (((hi - lo).maxCoeff() + 2 * radius) / voxel > kMaxVoxelsAcross)
    throw InputError("--voxel", "too small: the swept volume would be more than " +
                                    std::to_string(static_cast<int>(kMaxVoxelsAcross)) +
                                    " voxels across");
}

/// The mesh's triangles as OpenVDB takes them (the same at every pose).
std::vector<openvdb::Vec3I> vdb_triangles(const TriangleMesh& mesh) {
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    triangles.emplace_back(t[0], t[1], t[2]);
  return triangles;
}

/// The part at pose X as a narrow-band level set (exact distances; `band` voxels outside).
openvdb::FloatGrid::Ptr rasterise(const TriangleMesh& mesh,
                                  const std::vector<openvdb::Vec3I>& triangles,
                                  const Eigen::Isometry3d& X, const openvdb::math::Transform& xform,
                                  float band) {
  std::vector<openvdb::Vec3s> points;
  points.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const Eigen::Vector3d w = X * v;
    points.emplace_back(xform.worldToIndex(openvdb::Vec3d(w.x(), w.y(), w.z())));
  }
  const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(
      points, triangles);
  return openvdb::tools::meshToVolume<openvdb::FloatGrid>(adapter, xform, band, 2.0f,
                                                          openvdb::tools::DISABLE_RENORMALIZATION);
}

/// The iso-surface of the union as triangles (OpenVDB's quads split in two), facing outwards.
TriangleMesh mesh_of(const openvdb::FloatGrid& grid, double iso) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, iso);
  TriangleMesh mesh;
  for (const openvdb::Vec3s& p : points)
    mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  for (const openvdb::Vec3I& t : triangles)
    mesh.triangles.push_back({t[0], t[1], t[2]});
  for (const openvdb::Vec4I& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  double volume = 0.0;  // six times the signed volume: negative when the triangles face inwards
  for (const auto& t : mesh.triangles)
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  if (volume < 0)
    for (auto& t : mesh.triangles)
      std::swap(t[1], t[2]);
  return mesh;
}

}  // namespace

double default_envelope_voxel(const Body& object) {
  const auto [lo, hi] = object_mesh(object).mesh.bounding_box();
  return (hi - lo).maxCoeff() / 48.0;
}

MotionEnvelope motion_envelope(const Body& object, const Path& path, const SE3Space& space,
                               double voxel, const std::stop_token& stop) {
  if (!(voxel > 0.0) || !std::isfinite(voxel))
    throw InputError("--voxel", "must be a positive number, got " + std::to_string(voxel));
  if (path.empty())
    throw InputError("path", "has no state");
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });
  const ObjectMesh part = object_mesh(object);
  const std::vector<Config> poses = rasterised_poses(path, space, part.radius, voxel);
  check_extent(poses, part.radius, voxel);
  const double iso = voxel / 2 + std::numbers::sqrt3 * voxel + part.gap;
  const auto band = static_cast<float>(std::ceil(iso / voxel) + 2);
  const auto xform = openvdb::math::Transform::createLinearTransform(voxel);
  const std::vector<openvdb::Vec3I> triangles = vdb_triangles(part.mesh);
  openvdb::FloatGrid::Ptr swept;
  for (const Config& q : poses) {
    if (stop.stop_requested())
      return {{}, voxel, iso + voxel, 0};
    openvdb::FloatGrid::Ptr grid = rasterise(part.mesh, triangles, q.pose(), *xform, band);
    if (!swept)
      swept = grid;
    else
      openvdb::tools::csgUnion(*swept, *grid);
  }
  return {mesh_of(*swept, iso), voxel, iso + voxel, poses.size()};
}

}  // namespace tandem

#include "tandem/scene/geometry.hpp"

#include <cmath>
#include <numbers>

namespace tandem {
namespace {

using Tri = std::array<std::uint32_t, 3>;

std::uint32_t add_vertex(TriangleMesh& m, const Eigen::Vector3d& v) {
  m.vertices.push_back(v);
  return static_cast<std::uint32_t>(m.vertices.size() - 1);
}

TriangleMesh box_mesh(const Box& box) {
  TriangleMesh m;
  const Eigen::Vector3d h = 0.5 * box.size;
  for (int i = 0; i < 8; ++i) {
    add_vertex(m, Eigen::Vector3d((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                                  (i & 4) ? h.z() : -h.z()));
  }
  // Outward-facing, counter-clockwise.
  const Tri faces[] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                       {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  m.triangles.assign(std::begin(faces), std::end(faces));
  return m;
}

TriangleMesh cylinder_mesh(const Cylinder& c, int segments) {
  TriangleMesh m;
  const double h = 0.5 * c.length;
  const auto n = static_cast<std::uint32_t>(segments);
  const std::uint32_t bottom = add_vertex(m, {0, 0, -h});
  const std::uint32_t top = add_vertex(m, {0, 0, h});
  for (std::uint32_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    add_vertex(m, {c.radius * std::cos(a), c.radius * std::sin(a), -h});
    add_vertex(m, {c.radius * std::cos(a), c.radius * std::sin(a), h});
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t b0 = 2 + 2 * i, t0 = b0 + 1;
    const std::uint32_t b1 = 2 + 2 * ((i + 1) % n), t1 = b1 + 1;
    m.triangles.push_back({bottom, b1, b0});
    m.triangles.push_back({top, t0, t1});
    m.triangles.push_back({b0, b1, t1});
    m.triangles.push_back({b0, t1, t0});
  }
  return m;
}

TriangleMesh sphere_mesh(const Sphere& s, int segments) {
  TriangleMesh m;
  const auto rings = static_cast<std::uint32_t>(std::max(2, segments / 2));
  const auto sectors = static_cast<std::uint32_t>(segments);
  const std::uint32_t south = add_vertex(m, {0, 0, -s.radius});
  for (std::uint32_t r = 1; r < rings; ++r) {
    const double polar = std::numbers::pi * r / rings;
    for (std::uint32_t k = 0; k < sectors; ++k) {
      const double a = 2.0 * std::numbers::pi * k / sectors;
      add_vertex(m, {s.radius * std::sin(polar) * std::cos(a),
                     s.radius * std::sin(polar) * std::sin(a), -s.radius * std::cos(polar)});
    }
  }
  const std::uint32_t north = add_vertex(m, {0, 0, s.radius});
  auto at = [&](std::uint32_t ring, std::uint32_t k) {
    return 1 + (ring - 1) * sectors + k % sectors;
  };
  for (std::uint32_t k = 0; k < sectors; ++k) {
    m.triangles.push_back({south, at(1, k + 1), at(1, k)});
    m.triangles.push_back({north, at(rings - 1, k), at(rings - 1, k + 1)});
    for (std::uint32_t r = 1; r + 1 < rings; ++r) {
      m.triangles.push_back({at(r, k), at(r, k + 1), at(r + 1, k + 1)});
      m.triangles.push_back({at(r, k), at(r + 1, k + 1), at(r + 1, k)});
    }
  }
  return m;
}

}  // namespace

TriangleMesh tessellate(const Geometry& geometry, int segments) {
  struct Visitor {
    int segments;
    TriangleMesh operator()(const Box& b) const { return box_mesh(b); }
    TriangleMesh operator()(const Cylinder& c) const { return cylinder_mesh(c, segments); }
    TriangleMesh operator()(const Sphere& s) const { return sphere_mesh(s, segments); }
    TriangleMesh operator()(const MeshShape& m) const { return *m.mesh; }
  };
  return std::visit(Visitor{std::max(segments, 3)}, geometry);
}

TriangleMesh body_mesh(const Body& body, int segments) {
  TriangleMesh out;
  for (const Part& part : body.parts) {
    const TriangleMesh m = tessellate(part.geometry, segments);
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (const Eigen::Vector3d& v : m.vertices)
      out.vertices.push_back(part.pose * v);
    for (const auto& t : m.triangles)
      out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return out;
}

const char* geometry_kind(const Geometry& geometry) {
  static constexpr const char* kNames[] = {"box", "sphere", "cylinder", "mesh"};
  return kNames[geometry.index()];
}

}  // namespace tandem

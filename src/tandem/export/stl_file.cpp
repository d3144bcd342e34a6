#include "tandem/export/stl_file.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "tandem/core/error.hpp"

namespace tandem {
namespace {

static_assert(std::endian::native == std::endian::little, "STL is little-endian");

void put_vector(std::ostream& out, const Eigen::Vector3d& v) {
  const std::array<float, 3> f{static_cast<float>(v.x()), static_cast<float>(v.y()),
                               static_cast<float>(v.z())};
  out.write(reinterpret_cast<const char*>(f.data()), sizeof f);
}

}  // namespace

void write_stl(const TriangleMesh& mesh, const std::string& file, const std::string& header) {
  std::ofstream out(file, std::ios::binary);
  if (!out)
    throw InputError(file, "cannot be written");
  write_stl(mesh, out, header);
  if (!out.flush())
    throw InputError(file, "could not be written completely");
}

void write_stl(const TriangleMesh& mesh, std::ostream& out, const std::string& header) {
  std::array<char, 80> head{};
  std::memcpy(head.data(), header.data(), std::min(header.size(), head.size()));
  out.write(head.data(), head.size());
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  const std::uint16_t attribute = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]],
                          &c = mesh.vertices[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    put_vector(out, n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : n);
    put_vector(out, a);
    put_vector(out, b);
    put_vector(out, c);
    out.write(reinterpret_cast<const char*>(&attribute), sizeof attribute);
  }
}

}  // namespace tandem

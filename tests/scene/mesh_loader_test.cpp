#include "tandem/scene/mesh_loader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

const char* kTetrahedronObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

const char* kTriangleStl =
    "solid t\n"
    " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 2 0 0\n   vertex 0 2 0\n  "
    "endloop\n endfacet\n"
    "endsolid t\n";

/// Expects load_mesh to throw an InputError whose message names the file and contains `fault`.
void expect_rejected(const std::filesystem::path& file, const std::string& fault) {
  try {
    load_mesh(file);
    FAIL() << "accepted " << file;
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
    EXPECT_THAT(e.what(), HasSubstr(fault));
  }
}

TEST(MeshLoader, ReadsObj) {
  TempDir dir;
  const LoadedMesh m = load_mesh(dir.write("t.obj", kTetrahedronObj));
  EXPECT_EQ(m.mesh.triangle_count(), 4u);
  EXPECT_EQ(m.degenerate_removed, 0u);
  auto [lo, hi] = m.mesh.bounding_box();
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(0, 0, 0)));
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(1, 1, 1)));
}

TEST(MeshLoader, ReadsAsciiStl) {
  TempDir dir;
  const LoadedMesh m = load_mesh(dir.write("t.stl", kTriangleStl));
  ASSERT_EQ(m.mesh.triangle_count(), 1u);
  // Single precision, as OMPL.app computes it.
  EXPECT_LT((m.vertex_mean - Eigen::Vector3d(2.0 / 3, 2.0 / 3, 0)).norm(), 1e-6);
}

TEST(MeshLoader, RemovesDegenerateTriangles) {
  TempDir dir;
  const auto file = dir.write("d.obj",
                              "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n"
                              "f 1 2 3\nf 1 2 4\n");
  const LoadedMesh m = load_mesh(file);
  EXPECT_EQ(m.mesh.triangle_count(), 1u);
  EXPECT_EQ(m.degenerate_removed, 1u);
}

TEST(MeshLoader, RejectsAMeshOfOnlyDegenerateTriangles) {
  TempDir dir;
  expect_rejected(dir.write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"), "no triangles");
}

TEST(MeshLoader, RejectsAMeshWithoutTriangles) {
  TempDir dir;
  expect_rejected(dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 2 1 0\n"), "");
}

TEST(MeshLoader, RejectsMissingFilesAndOtherFormats) {
  TempDir dir;
  expect_rejected(dir.path() / "absent.stl", "no such file");
  expect_rejected(dir.write("model.blend", "whatever"), "unsupported mesh format");
  expect_rejected(dir.path(), "unsupported mesh format");
}

// A NUL byte ends the name the file system sees: "robot.ply\0.dae" would be checked as Collada
// and read by assimp as robot.ply (a fuzzing finding that hung assimp's PLY reader).
TEST(MeshLoader, RefusesAFileNameWithANulByte) {
  TempDir dir;
  const std::filesystem::path ply = dir.write("robot.ply", "ply\nformat ascii 1.0\nelement vertex");
  EXPECT_THAT(test::error_message<InputError>(
                  [&] { load_mesh(ply.string() + std::string(1, '\0') + ".dae"); }),
              HasSubstr("the file name '" + ply.string() + "\\0...' holds a NUL byte"));
}

TEST(MeshLoader, RejectsMalformedFiles) {
  TempDir dir;
  expect_rejected(dir.write("garbage.dae", "<COLLADA><this is not xml"), "cannot read mesh");
  expect_rejected(dir.write("garbage.stl", std::string("\x00\x01\x02 binary junk",
                                                       sizeof("\x00\x01\x02 binary junk") - 1)),
                  "");
  expect_rejected(dir.write("bad.obj", "v 0 0 0\nf 1 2 3\n"), "");
}

}  // namespace
}  // namespace tandem

namespace tandem {
namespace {

// assimp 5.2 loops forever on a PLY "element" line without its count, and aborts the process on a
// face list its triangulation cannot follow (fuzzing findings): tandem refuses both first, and
// element counts the file cannot hold.
TEST(MeshLoader, RefusesPlyFilesAssimpCannotRead) {
  TempDir dir;
  expect_rejected(dir.write("h.ply", "ply\nformat ascii 1.0\nelement vertex\nend_header\n"),
                  "malformed PLY header line 'element vertex'");
  expect_rejected(dir.write("e.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"),
                  "no 'end_header'");
  // A name run into digits: assimp read it as a count of billions (22 GB; a cfg fuzz finding).
  expect_rejected(dir.write("n.ply", "ply\nformat ascii 1.0\nelement 8888vertex 4\nend_header\n"),
                  "malformed PLY header line 'element 8888vertex 4'");
  const std::string faces =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 7\n";
  EXPECT_THROW(load_mesh(dir.write("f.ply", faces)), InputError);
  // assimp allocates what a count declares before it reads (25 GB here; a cfg fuzz finding).
  std::string huge = faces;
  huge.replace(huge.find("element face 2"), 14, "element face 8888888888888888885");
  expect_rejected(dir.write("c.ply", huge),
                  "c.ply:7: element 'face' declares 8888888888888888885 entries, more than the "
                  "file holds after its header");
}

}  // namespace
}  // namespace tandem

namespace tandem {
namespace {

std::string collada_square(const std::string& indices) {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <library_geometries><geometry id="wall"><mesh>
    <source id="pos"><float_array id="pos-array" count="12">-1 -1 0 1 -1 0 1 1 0 -1 1 0</float_array>
      <technique_common><accessor source="#pos-array" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="vtx"><input semantic="POSITION" source="#pos"/></vertices>
    <triangles count="2"><input semantic="VERTEX" source="#vtx" offset="0"/><p>)" +
         indices + R"(</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="n"><instance_geometry url="#wall"/>
  </node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

/// The square with one piece of its text replaced.
std::string collada_square_with(const std::string& from, const std::string& to) {
  std::string text = collada_square("0 1 2 0 2 3");
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(MeshLoader, RefusesColladaArraysWithoutACountAndAccessorsBeyondTheirArray) {
  test::TempDir dir;
  // assimp 5.2 read through a null pointer on this one (the cfg fuzz target's finding).
  expect_rejected(dir.write("no-count.dae", collada_square_with("count=\"12\"", "\xa7ount=\"12\"")),
                  "<float_array> has no whole-number count");
  expect_rejected(dir.write("short.dae", collada_square_with("count=\"12\"", "count=\"11\"")),
                  "reads beyond its array 'pos-array'");
  expect_rejected(
      dir.write("offset.dae", collada_square_with("stride=\"3\"", "stride=\"3\" offset=\"1\"")),
      "reads beyond its array");
  expect_rejected(dir.write("elsewhere.dae", collada_square_with("#pos-array", "#other")),
                  "names no array of the file");
  expect_rejected(
      dir.write("huge.dae", collada_square_with("count=\"4\"", "count=\"99999999999\"")),
      "<accessor> has no whole-number count");
}

TEST(MeshLoader, ReadsColladaAndRefusesAnIndexListWithAStrayByte) {
  test::TempDir dir;
  EXPECT_EQ(load_mesh(dir.write("good.dae", collada_square("0 1 2 0 2 3"))).mesh.triangles.size(),
            2u);
  // assimp 5.2 ran out of memory on this one (the cfg fuzz target's finding).
  const auto bad = dir.write("bad.dae", collada_square("0 1 2 0\xff"
                                                       "2 3"));
  expect_rejected(bad, "<p> list");
}

}  // namespace
}  // namespace tandem

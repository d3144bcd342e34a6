#include "tandem/scene/urdf_loader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"

namespace tandem {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

const char* kFixture = R"(<?xml version="1.0"?>
<robot name="fixture">
  <link name="base">
    <visual><geometry><box size="1 1 1"/></geometry>
      <material name="blue"><color rgba="0.2 0.4 0.6 1"/></material></visual>
    <collision><origin xyz="0 0 0.5"/><geometry><box size="1 2 1"/></geometry></collision>
  </link>
  <link name="post">
    <collision><geometry><cylinder radius="0.1" length="2"/></geometry></collision>
  </link>
  <link name="ball">
    <visual><geometry><sphere radius="0.3"/></geometry></visual>
  </link>
  <link name="shell">
    <collision><geometry><mesh filename="meshes/tet.obj" scale="2 2 2"/></geometry></collision>
  </link>
  <joint name="base_post" type="fixed"><parent link="base"/><child link="post"/><origin xyz="1 0 0"/></joint>
  <joint name="post_ball" type="fixed"><parent link="post"/><child link="ball"/>
    <origin xyz="0 0 1" rpy="0 0 1.5707963267948966"/></joint>
  <joint name="base_shell" type="fixed"><parent link="base"/><child link="shell"/><origin xyz="0 3 0"/></joint>
</robot>
)";

const char* kTetrahedronObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string expect_error(const std::filesystem::path& file, UrdfRole role,
                         const FileAccess& access = {}) {
  try {
    load_urdf(file, role, access);
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(file.string()));
    return e.what();
  }
  ADD_FAILURE() << "accepted " << file;
  return {};
}

TEST(UrdfLoader, ReadsPrimitivesMeshesAndTheJointTree) {
  TempDir dir;
  dir.write("meshes/tet.obj", kTetrahedronObj);
  const Body body =
      load_urdf(dir.write("fixture.urdf", kFixture), UrdfRole::object, {{dir.path()}});
  EXPECT_EQ(body.name, "fixture");
  ASSERT_EQ(body.parts.size(), 4u);
  // base: collision geometry (not the visual), posed by its origin.
  ASSERT_TRUE(std::holds_alternative<Box>(body.parts[0].geometry));
  EXPECT_TRUE(std::get<Box>(body.parts[0].geometry).size.isApprox(Eigen::Vector3d(1, 2, 1)));
  EXPECT_TRUE(body.parts[0].pose.translation().isApprox(Eigen::Vector3d(0, 0, 0.5)));
  // post: cylinder at the joint origin.
  ASSERT_TRUE(std::holds_alternative<Cylinder>(body.parts[1].geometry));
  EXPECT_TRUE(body.parts[1].pose.translation().isApprox(Eigen::Vector3d(1, 0, 0)));
  // ball: no collision element, so its visual; joints compose.
  ASSERT_TRUE(std::holds_alternative<Sphere>(body.parts[2].geometry));
  EXPECT_TRUE(body.parts[2].pose.translation().isApprox(Eigen::Vector3d(1, 0, 1)));
  EXPECT_TRUE((body.parts[2].pose.linear() * Eigen::Vector3d::UnitX())
                  .isApprox(Eigen::Vector3d::UnitY(), 1e-9));
  // shell: the mesh, scaled.
  ASSERT_TRUE(std::holds_alternative<MeshShape>(body.parts[3].geometry));
  auto [lo, hi] = std::get<MeshShape>(body.parts[3].geometry).mesh->bounding_box();
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(2, 2, 2)));
  EXPECT_NEAR(body.color.b, 0.6, 1e-6);
}

TEST(UrdfLoader, RefusesMovableJointsInTheObjectButNotInObstacles) {
  TempDir dir;
  std::string text = kFixture;
  text.replace(text.find("\"base_post\" type=\"fixed\""), 24, "\"base_post\" type=\"revolute\"");
  text.replace(text.find("<origin xyz=\"1 0 0\"/>"), 21,
               "<origin xyz=\"1 0 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" "
               "effort=\"1\" velocity=\"1\"/>");
  dir.write("meshes/tet.obj", kTetrahedronObj);
  const auto file = dir.write("moving.urdf", text);
  EXPECT_THAT(expect_error(file, UrdfRole::object), HasSubstr("joint 'base_post' is movable"));
  EXPECT_EQ(load_urdf(file, UrdfRole::obstacle, {}).parts.size(), 4u);
}

TEST(UrdfLoader, RejectsMalformedFiles) {
  TempDir dir;
  EXPECT_THAT(expect_error(dir.path() / "absent.urdf", UrdfRole::object),
              HasSubstr("no such file"));
  EXPECT_THAT(
      expect_error(dir.write("broken.urdf", "<robot name='x'><link name='a'>"), UrdfRole::object),
      HasSubstr("not a valid URDF"));
  EXPECT_THAT(expect_error(dir.write("empty.urdf", "<robot name='x'><link name='a'/></robot>"),
                           UrdfRole::object),
              HasSubstr("no link has collision or visual geometry"));
}

// urdfdom accepts joints that form a loop. Reached from the root, the walk down the tree never
// ended (a stack overflow); out of its reach, the loop's links were dropped without a word, and
// urdfdom's model leaked (a finding of the scenario fuzz target).
TEST(UrdfLoader, RejectsJointsThatFormALoop) {
  TempDir dir;
  auto urdf = [&](const std::string& name, const std::string& joints) {
    return dir.write(name,
                     "<robot name='x'>"
                     "<link name='base'><collision><geometry><box size='1 1 1'/></geometry>"
                     "</collision></link>"
                     "<link name='a'><collision><geometry><sphere radius='1'/></geometry>"
                     "</collision></link>"
                     "<link name='b'><collision><geometry><sphere radius='1'/></geometry>"
                     "</collision></link>" +
                         joints + "</robot>");
  };
  auto joint = [](const std::string& name, const std::string& parent, const std::string& child) {
    return "<joint name='" + name + "' type='fixed'><parent link='" + parent + "'/><child link='" +
           child + "'/></joint>";
  };
  const std::string a_b = joint("ab", "a", "b"), b_a = joint("ba", "b", "a");
  EXPECT_THAT(expect_error(urdf("reached.urdf", joint("base_a", "base", "a") + a_b + b_a),
                           UrdfRole::obstacle),
              HasSubstr("is the child of two joints (the joints form a loop)"));
  EXPECT_THAT(expect_error(urdf("island.urdf", a_b + b_a), UrdfRole::obstacle),
              HasSubstr("link 'a' is not in the tree of joints from the root link 'base' (the "
                        "joints form a loop)"));
  EXPECT_EQ(load_urdf(urdf("tree.urdf", joint("base_a", "base", "a") + a_b), UrdfRole::obstacle, {})
                .parts.size(),
            3u);
}

TEST(UrdfLoader, RejectsNonsensicalSizes) {
  TempDir dir;
  auto urdf = [&](const std::string& name, const std::string& geometry) {
    return dir.write(name, "<robot name='x'><link name='a'><collision><geometry>" + geometry +
                               "</geometry></collision></link></robot>");
  };
  EXPECT_THAT(expect_error(urdf("box.urdf", "<box size='1 -2 1'/>"), UrdfRole::object),
              HasSubstr("box size"));
  EXPECT_THAT(expect_error(urdf("sphere.urdf", "<sphere radius='0'/>"), UrdfRole::object),
              HasSubstr("sphere radius"));
  EXPECT_THAT(
      expect_error(urdf("cyl.urdf", "<cylinder radius='1' length='nan'/>"), UrdfRole::object),
      HasSubstr(""));
  dir.write("tet.obj", kTetrahedronObj);
  EXPECT_THAT(expect_error(urdf("scale.urdf", "<mesh filename='tet.obj' scale='1 0 1'/>"),
                           UrdfRole::object),
              HasSubstr("mesh scale"));
}

TEST(UrdfLoader, ResolvesMeshesOnlyInsideTheAllowedFolders) {
  TempDir dir;
  dir.write("outside/tet.obj", kTetrahedronObj);
  auto urdf = [&](const std::string& name, const std::string& file) {
    return dir.write("inside/" + name,
                     "<robot name='x'><link name='a'><collision><geometry><mesh filename='" + file +
                         "'/></geometry></collision></link></robot>");
  };
  const FileAccess inside{{dir.path() / "inside"}};
  EXPECT_THAT(expect_error(urdf("up.urdf", "../outside/tet.obj"), UrdfRole::object, inside),
              HasSubstr("outside the folders tandem may read"));
  EXPECT_THAT(expect_error(urdf("pkg.urdf", "package://robot/tet.obj"), UrdfRole::object, inside),
              HasSubstr("package:// URIs are not supported"));
  EXPECT_THAT(expect_error(urdf("missing.urdf", "nothere.obj"), UrdfRole::object, inside),
              HasSubstr("no such file"));
  const FileAccess both{{dir.path() / "inside", dir.path() / "outside"}};
  EXPECT_EQ(load_urdf(urdf("ok.urdf", "../outside/tet.obj"), UrdfRole::object, both).parts.size(),
            1u);
}

}  // namespace
}  // namespace tandem

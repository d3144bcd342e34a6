#include "tandem/scene/scenario_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/runs/run_spec.hpp"

namespace tandem {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

const char* kScenario = R"(name = "test scene"
description = "every kind of geometry"

[space]
min = [-5, -5, 0]
max = [5, 5, 3]
resolution = 0.02
rotation_weight = 1.0

[object]
name = "part"
color = "#ff8000"
shapes = [
  { box = [1, 0.2, 0.2] },
  { sphere = 0.1, position = [0.5, 0, 0] },
]

[[obstacle]]
name = "pillar"
cylinder = { radius = 0.2, length = 3 }
position = [1, 1, 1.5]
color = [0.1, 0.2, 0.3]

[[obstacle]]
name = "tilted plate"
box = [2, 2, 0.05]
position = [0, 0, 2]
rpy_deg = [10, 0, 0]

[[obstacle]]
name = "shell"
mesh = "tet.obj"
scale = 2.0
position = [-3, -3, 0]

[[obstacle]]
name = "fixture"
urdf = "fixture.urdf"
position = [3, -3, 0]
quaternion = [0, 0, 0.7071067811865476, 0.7071067811865476]

[start]
position = [-4, 0, 1]

[goal]
position = [4, 0, 1]
rpy_deg = [0, 0, 90]

[planner]
name = "rrt"
extend = "last-valid"
range = 0.5
goal_bias = 0.1
time_limit = 5
seed = 42
)";

const char* kTetrahedronObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

struct ScenarioDir {
  TempDir dir;
  ScenarioDir() {
    dir.write("tet.obj", kTetrahedronObj);
    dir.write("fixture.urdf",
              "<robot name='f'><link name='a'><collision><geometry><box size='1 1 1'/></geometry>"
              "</collision></link></robot>");
  }
  /// Loads the scenario and checks its [planner] tunables, as every command does.
  Problem load(const std::string& text) const {
    Problem p = load_scenario_file(dir.write("s.toml", text), FileAccess{{dir.path()}});
    check_hints(p.hints, p.source);
    return p;
  }
  /// The error for a scenario that is kScenario with `from` replaced by `to`.
  std::string error(const std::string& from, const std::string& to) const {
    std::string text = kScenario;
    const auto at = text.find(from);
    if (at == std::string::npos) {
      ADD_FAILURE() << "'" << from << "' not in the fixture";
      return {};
    }
    text.replace(at, from.size(), to);
    try {
      load(text);
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr((dir.path() / "s.toml").string()));
      return e.what();
    }
    ADD_FAILURE() << "accepted a scenario with '" << to << "'";
    return {};
  }
};

TEST(ScenarioFile, ReadsEveryKindOfGeometry) {
  ScenarioDir s;
  const Problem p = s.load(kScenario);
  EXPECT_EQ(p.name, "test scene");
  EXPECT_EQ(p.space.kind(), SpaceKind::se3);
  EXPECT_DOUBLE_EQ(p.space.resolution(), 0.02);
  EXPECT_DOUBLE_EQ(p.space.weights().rotation, 1.0);
  EXPECT_EQ(p.scene.object.parts.size(), 2u);
  EXPECT_NEAR(p.scene.object.color.g, 128.0 / 255.0, 1e-12);
  ASSERT_EQ(p.scene.obstacles.size(), 4u);
  EXPECT_EQ(p.scene.obstacles[1].name, "tilted plate");
  const Eigen::Vector3d normal =
      p.scene.obstacles[1].parts[0].pose.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(std::acos(normal.z()) * 180 / std::numbers::pi, 10.0, 1e-9);
  EXPECT_TRUE(std::holds_alternative<MeshShape>(p.scene.obstacles[2].parts[0].geometry));
  const Eigen::Vector3d fixture_x =
      p.scene.obstacles[3].parts[0].pose.linear() * Eigen::Vector3d::UnitX();
  EXPECT_TRUE(fixture_x.isApprox(Eigen::Vector3d::UnitY(), 1e-9));
  EXPECT_TRUE(p.goal.t.isApprox(Eigen::Vector3d(4, 0, 1)));
  EXPECT_NEAR(SE3Space::yaw(p.goal.q), std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(p.hints.planner, "rrt");
  EXPECT_EQ(*p.hints.seed, 42u);
  EXPECT_DOUBLE_EQ(*p.hints.time_limit, 5.0);
  const RunSpec spec = default_spec("rrt", p.hints);
  EXPECT_EQ(spec.settings.extend, ExtendMode::last_valid);
  EXPECT_DOUBLE_EQ(spec.settings.range, 0.5);
  EXPECT_DOUBLE_EQ(spec.settings.goal_bias, 0.1);
}

TEST(ScenarioFile, ReportsUnknownKeysWithTheirLine) {
  ScenarioDir s;
  EXPECT_THAT(s.error("[planner]\n", "[planner]\nrnage = 3\n"),
              HasSubstr("s.toml:50: unknown parameter 'rnage' (known: range, "));
  EXPECT_THAT(s.error("name = \"pillar\"", "name = \"pillar\"\nradius = 3"),
              HasSubstr("unknown key 'radius'"));
}

TEST(ScenarioFile, ReportsMalformedToml) {
  ScenarioDir s;
  EXPECT_THAT(s.error("min = [-5, -5, 0]", "min = [-5, -5, 0"), HasSubstr("invalid TOML"));
}

TEST(ScenarioFile, ReportsMissingSectionsAndKeys) {
  ScenarioDir s;
  EXPECT_THAT(s.error("[goal]\nposition = [4, 0, 1]", "[goal]\n"),
              HasSubstr("goal needs 'position'"));
  EXPECT_THAT(s.error("name = \"pillar\"\n", ""), HasSubstr("needs 'name'"));
  EXPECT_THAT(s.error("cylinder = { radius = 0.2, length = 3 }", ""),
              HasSubstr("needs exactly one geometry"));
  EXPECT_THAT(s.error("cylinder = { radius = 0.2, length = 3 }",
                      "cylinder = { radius = 0.2, length = 3 }\nsphere = 1"),
              HasSubstr("several given"));
}

TEST(ScenarioFile, ReportsValuesOfTheWrongTypeOrRange) {
  ScenarioDir s;
  EXPECT_THAT(s.error("box = [2, 2, 0.05]", "box = \"big\""),
              HasSubstr("box must be an array of numbers"));
  EXPECT_THAT(s.error("box = [2, 2, 0.05]", "box = [2, 2]"), HasSubstr("box must have 3 numbers"));
  EXPECT_THAT(s.error("box = [2, 2, 0.05]", "box = [2, -2, 0.05]"),
              HasSubstr("sizes must be positive"));
  EXPECT_THAT(s.error("radius = 0.2", "radius = -0.2"), HasSubstr("radius must be positive"));
  EXPECT_THAT(s.error("\"#ff8000\"", "\"#ff80\""), HasSubstr("color must be"));
  EXPECT_THAT(s.error("[0.1, 0.2, 0.3]", "[0.1, 2, 0.3]"),
              HasSubstr("components must be in [0, 1]"));
  EXPECT_THAT(s.error("max = [5, 5, 3]", "max = [5, -6, 3]"),
              HasSubstr("space.min must be below space.max"));
  EXPECT_THAT(s.error("resolution = 0.02", "resolution = 2"), HasSubstr("resolution"));
  EXPECT_THAT(s.error("seed = 42", "seed = -1"), HasSubstr("seed must be a non-negative integer"));
  EXPECT_THAT(s.error("goal_bias = 0.1", "goal_bias = 1.5"),
              HasSubstr("goal_bias must be a number in [0, 1], not 1.5"));
  EXPECT_THAT(s.error("name = \"rrt\"", "name = \"prm\""),
              HasSubstr("planner.name: unknown planner 'prm' (known: birrt, rrt"));
  EXPECT_THAT(s.error("extend = \"last-valid\"", "extend = \"lazy\""),
              HasSubstr("extend must be one of classic, last-valid, not 'lazy'"));
  EXPECT_THAT(s.error("goal_bias = 0.1", "goal_bias = 0.1\nalpha = nan"),
              HasSubstr("alpha must be a number in [0, 1], not nan"));
  EXPECT_THAT(s.error("scale = 2.0", "scale = 0"), HasSubstr("scale must be positive"));
  EXPECT_THAT(s.error("rpy_deg = [10, 0, 0]", "rpy_deg = [10, 0, 0]\nquaternion = [0, 0, 0, 1]"),
              HasSubstr("more than once"));
  EXPECT_THAT(s.error("quaternion = [0, 0, 0.7071067811865476, 0.7071067811865476]",
                      "quaternion = [0, 0, 0, 0]"),
              HasSubstr("must not be zero"));
}

TEST(ScenarioFile, ReportsDuplicateObstacleNames) {
  ScenarioDir s;
  EXPECT_THAT(s.error("name = \"shell\"", "name = \"pillar\""),
              HasSubstr("'pillar' is used twice"));
}

TEST(ScenarioFile, ReportsFilesItCannotUse) {
  ScenarioDir s;
  EXPECT_THAT(s.error("mesh = \"tet.obj\"", "mesh = \"missing.stl\""), HasSubstr("no such file"));
  EXPECT_THAT(s.error("mesh = \"tet.obj\"", "mesh = \"/etc/passwd.stl\""),
              HasSubstr("outside the folders"));
  EXPECT_THAT(s.error("mesh = \"tet.obj\"", "mesh = \"tet.obj\\u0000.stl\""),
              HasSubstr("the file name 'tet.obj\\0...' holds a NUL byte"));
  s.dir.write("bad.urdf", "<robot");
  EXPECT_THAT(s.error("urdf = \"fixture.urdf\"", "urdf = \"bad.urdf\""),
              HasSubstr("not a valid URDF"));
}

TEST(ScenarioFile, ReadsPlanarScenes) {
  ScenarioDir s;
  const Problem p = s.load(R"(
[space]
kind = "planar"
min = [0, 0]
max = [10, 5]
[object]
box = [1, 0.5, 0.1]
[start]
position = [1, 1]
yaw_deg = 90
[goal]
position = [9, 4]
)");
  EXPECT_TRUE(p.space.planar());
  EXPECT_NEAR(SE3Space::yaw(p.start.q), std::numbers::pi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(p.start.t.z(), 0.0);
}

TEST(ScenarioFile, RefusesTiltsInPlanarScenes) {
  ScenarioDir s;
  EXPECT_THAT(test::error_message<InputError>([&] {
                return s.load(R"(
[space]
kind = "planar"
min = [0, 0]
max = [10, 5]
[object]
box = [1, 0.5, 0.1]
[start]
position = [1, 1]
rpy_deg = [0, 30, 0]
[goal]
position = [9, 4]
)");
              }),
              HasSubstr("must rotate about z only in a planar space (use yaw_deg)"));
}

}  // namespace
}  // namespace tandem

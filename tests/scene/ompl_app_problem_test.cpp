// OMPL.app's problems, read as OMPL.app reads them: every sample solution it ships validates.

#include "tandem/scene/ompl_app_problem.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "support/test_support.hpp"
#include "tandem/core/error.hpp"
#include "tandem/io/path_file.hpp"
#include "tandem/planning/path.hpp"
#include "tandem/planning/planner_registry.hpp"

namespace tandem {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

std::filesystem::path omplapp() {
  return test::shared_dir() / "benchmarks" / "omplapp";
}

class SamplePath : public ::testing::TestWithParam<std::string> {};

TEST_P(SamplePath, PassesCheckPath) {
  TANDEM_REQUIRE_SHARED_DATA();
  const auto cfg = omplapp() / (GetParam() + ".cfg");
  const Problem problem = load_ompl_app_problem(cfg);
  const Path path = read_path_file(omplapp() / (GetParam() + ".path"), problem.space);
  CollisionChecker checker(problem.scene);
  MotionValidator validator(problem.space, checker);
  const PathCheck check = check_path(path, validator);
  EXPECT_TRUE(check.valid) << check.describe();
  EXPECT_LT(problem.space.distance(path.front(), problem.start), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(OmplApp, SamplePath,
                         ::testing::Values("3D/Easy", "3D/Twistycool", "3D/cubicles",
                                           "3D/alpha-1.2", "3D/alpha-1.5", "3D/Apartment",
                                           "2D/Maze_planar", "2D/BugTrap_planar"),
                         [](const auto& test_info) {
                           std::string n = test_info.param.substr(3);
                           for (char& c : n)
                             c = (c == '-' || c == '.') ? '_' : c;
                           return n;
                         });

TEST(OmplAppProblem, ChecksAreTightEnoughToRejectAShiftedPath) {
  // The sample paths pass narrow passages: moving them by 1% of the extent makes them collide, so a
  // loader with the wrong conventions (no re-centring, no Y-up turn) cannot pass the test above by
  // luck.
  TANDEM_REQUIRE_SHARED_DATA();
  for (const std::string name : {"3D/alpha-1.5", "3D/Twistycool"}) {
    const Problem problem = load_ompl_app_problem(omplapp() / (name + ".cfg"));
    Path path = read_path_file(omplapp() / (name + ".path"), problem.space);
    for (auto& q : path)
      q.t.x() += 0.01 * problem.space.translation_extent();
    CollisionChecker checker(problem.scene);
    MotionValidator validator(problem.space, checker);
    EXPECT_FALSE(check_path(path, validator).valid) << name;
  }
}

TEST(OmplAppProblem, ReadsEasyAsOmplAppDoes) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem p = load_ompl_app_problem(omplapp() / "3D" / "Easy.cfg");
  EXPECT_EQ(p.name, "Easy");
  EXPECT_FALSE(p.space.planar());
  EXPECT_TRUE(
      p.space.bounds().min.isApprox(Eigen::Vector3d(14.4604492188, -24.25, -504.855102539)));
  EXPECT_TRUE(p.start.t.isApprox(Eigen::Vector3d(270, 160, -200)));
  EXPECT_TRUE(p.goal.t.isApprox(Eigen::Vector3d(270, 160, -400)));
  EXPECT_DOUBLE_EQ(*p.hints.time_limit, 20.0);
  EXPECT_EQ(*p.hints.run_count, 30u);
  // The robot mesh is centred on the mean of its vertices.
  const auto& robot = *std::get<MeshShape>(p.scene.object.parts[0].geometry).mesh;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& v : robot.vertices)
    mean += v / static_cast<double>(robot.vertices.size());
  EXPECT_LT(mean.norm(), 1e-3);
}

TEST(OmplAppProblem, ReadsPlannerRangesAndPlanarProblems) {
  TANDEM_REQUIRE_SHARED_DATA();
  const Problem alpha = load_ompl_app_problem(omplapp() / "3D" / "alpha-1.5.cfg");
  EXPECT_DOUBLE_EQ(alpha.hints.range.at("rrt"), 10.0);
  EXPECT_EQ(alpha.hints.range.count("birrt"), 0u);
  const Problem maze = load_ompl_app_problem(omplapp() / "2D" / "Maze_planar.cfg");
  EXPECT_TRUE(maze.space.planar());
  EXPECT_NEAR(SE3Space::yaw(maze.goal.q), 0.802851455917, 1e-12);
}

/// A cfg whose meshes are the shared Easy meshes, with `problem` as its [problem] body.
std::filesystem::path write_cfg(const TempDir& dir, const std::string& problem) {
  const auto meshes = omplapp() / "3D";
  return dir.write("p.cfg", "[problem]\nrobot = " + (meshes / "Easy_robot.dae").string() +
                                "\nworld = " + (meshes / "Easy_env.dae").string() + "\n" + problem);
}

std::string error_of(const std::filesystem::path& cfg) {
  SCOPED_TRACE(cfg.string());
  return test::error_message<InputError>([&] { load_ompl_app_problem(cfg); });
}

TEST(OmplAppProblem, ReadsPlannerSectionsThatNameAPlannerTwiceAndPlansTheirProblem) {
  TANDEM_REQUIRE_SHARED_DATA();
  // As OMPL's own benchmark files compare two settings of one planner: each repetition starts a
  // new planner entry; tandem takes the first entry's settings.
  TempDir dir;
  const std::string easy =
      "start.x = 270.0\nstart.y = 160.0\nstart.z = -200.0\n"
      "start.theta = 0\nstart.axis.x = 1\nstart.axis.y = 0\nstart.axis.z = 0\n"
      "goal.x = 270.0\ngoal.y = 160.0\ngoal.z = -400.0\ngoal.theta = 0\n"
      "goal.axis.x = 1\ngoal.axis.y = 0\ngoal.axis.z = 0\n";
  const auto cfg = write_cfg(dir, easy +
                                      "[planner]\naps=\naps.name=APS1\naps.range=5\n"
                                      "rrtconnect=\nrrtconnect.range=30\n"
                                      "aps=\naps.name=APS4\naps.range=9\n"
                                      "rrtconnect=\nrrtconnect.range=60\n");
  const Problem p = load_ompl_app_problem(cfg);
  EXPECT_DOUBLE_EQ(p.hints.range.at("birrt"), 30.0);
  CollisionChecker checker(p.scene);
  MotionValidator validator(p.space, checker);
  PlannerSettings settings;
  settings.range = p.hints.range.at("birrt");
  auto planner = make_planner("birrt", validator, p.start, p.goal, settings);
  Termination t;
  t.time_limit_s = 60.0;
  ASSERT_EQ(planner->solve(t), PlannerStatus::solved);
  EXPECT_TRUE(check_path(planner->solution(), validator).valid);
  // Elsewhere a repeated key is still a mistake.
  EXPECT_THAT(error_of(write_cfg(dir, easy + "start.x = 1\n")),
              HasSubstr("key 'start.x' repeated (first on line 4)"));
}

TEST(OmplAppProblem, ReportsMalformedFiles) {
  TANDEM_REQUIRE_SHARED_DATA();
  TempDir dir;
  const std::string ends =
      "start.x=0\nstart.y=0\nstart.z=0\nstart.theta=0\ngoal.x=1\ngoal.y=0\ngoal.z=0\ngoal.theta="
      "0\n";
  EXPECT_THAT(error_of(dir.path() / "none.cfg"), HasSubstr("none.cfg: no such file"));
  EXPECT_THAT(error_of(dir.write("a.cfg", "robot = x\n")),
              HasSubstr("a.cfg:1: key outside of any [section]"));
  EXPECT_THAT(error_of(dir.write("b.cfg", "[problem\n")),
              HasSubstr("b.cfg:1: malformed section header"));
  EXPECT_THAT(error_of(dir.write("c.cfg", "[problem]\njust words\n")),
              HasSubstr("c.cfg:2: expected 'key = value'"));
  EXPECT_THAT(error_of(dir.write("d.cfg", "[benchmark]\ntime_limit=1\n")),
              HasSubstr("no [problem] section"));
  EXPECT_THAT(error_of(write_cfg(dir, ends + "strat.x=0\n")),
              HasSubstr("unknown key 'strat.x' in [problem]"));
  EXPECT_THAT(error_of(write_cfg(dir, "start.x=zero\n" + ends.substr(ends.find('\n') + 1))),
              HasSubstr("'start.x' is not a finite number"));
  EXPECT_THAT(error_of(write_cfg(dir, ends.substr(0, ends.find("goal.x")))),
              HasSubstr("[problem] has no 'goal.x'"));
  EXPECT_THAT(error_of(write_cfg(dir, ends + "[benchmark]\ntime_limit=-4\n")),
              HasSubstr("time_limit must be a positive number"));
  EXPECT_THAT(
      error_of(dir.write("e.cfg", "[problem]\nrobot = nothere.dae\nworld = nothere.dae\n" + ends)),
      HasSubstr("nothere.dae: no such file"));
  // The mesh opened would be named only up to the NUL byte: refused, naming the key and its line.
  const std::string robot = "robot = " + (omplapp() / "3D" / "Easy_robot.dae").string() + "\n";
  EXPECT_THAT(error_of(dir.write("f.cfg",
                                 "[problem]\n" + robot + "world = w.dae" + '\0' + ".stl\n" + ends)),
              HasSubstr("f.cfg:3: 'world': the file name 'w.dae\\0...' holds a NUL byte"));
  EXPECT_THAT(error_of(dir.write(
                  "g.cfg", "[problem]\nrobot = r.dae" + std::string(1, '\0') + ".stl\n" + ends)),
              HasSubstr("g.cfg:2: 'robot': the file name 'r.dae\\0...' holds a NUL byte"));
}

}  // namespace
}  // namespace tandem

// CAD assemblies from the command line: `tandem parts`, and a scenario whose obstacles and object
// come from a STEP file (tests/support/cad_assembly.hpp's housing, written by the test).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "support/cad_assembly.hpp"
#include "support/test_support.hpp"

namespace tandem {
namespace {

using test::run_tandem;
using test::TempDir;
using ::testing::HasSubstr;

struct RunResultLine {
  int code;
  std::string text;  ///< stdout and stderr
};

class CadCliTest : public ::testing::Test {
 protected:
  void SetUp() override { test::write_housing(step_); }

  /// A scenario taking `part` of the housing out to the side, between the block and the lid. The
  /// peg's frame is its centre: seated at z = 0.025, out at z = 0.06 (0.045 to 0.075).
  std::filesystem::path scenario(const std::string& part, const std::string& extra = "") {
    return dir_.write("peg-out.toml", R"(name = "peg-out"
[space]
min = [-0.2, -0.2, -0.05]
max = [0.2, 0.2, 0.15]
[assembly]
file = "housing.step"
part = ")" + part + R"("
)" + extra + R"(
[goal]
position = [0.1, 0.0, 0.06]
)");
  }

  std::filesystem::path path_file(const std::string& name, const std::string& states) {
    return dir_.write(name, states);
  }

  TempDir dir_;
  std::filesystem::path step_ = dir_.path() / "housing.step";
};

TEST_F(CadCliTest, PartsListsTheTreeWithSizesAndColours) {
  const auto r = run_tandem({"parts", step_.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("STEP, length unit 0.001 m"));
  EXPECT_THAT(r.out, HasSubstr("housing (assembly)\n  base [base-block]  0.1 x 0.08 x 0.04 m"));
  EXPECT_THAT(r.out, HasSubstr("  lid-1 [lid-assembly] (assembly)\n    lid [lid-plate]"));
  EXPECT_THAT(r.out, HasSubstr("#1933cc"));  // the base's blue (0.1, 0.2, 0.8)
}

TEST_F(CadCliTest, PartsAsJson) {
  const auto r = run_tandem({"parts", step_.string(), "--json", "--linear-deflection", "1e-5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["linear_deflection_m"].get<double>(), 1e-5);
  ASSERT_EQ(j["nodes"].size(), 6u);
  const auto& peg = j["nodes"][4];
  EXPECT_EQ(peg["path"], "housing/peg");
  EXPECT_NEAR(peg["position_m"][2].get<double>(), 0.01, 1e-12);
  EXPECT_NEAR(peg["size_m"][2].get<double>(), 0.03, 1e-9);
  EXPECT_EQ(peg["color"], "#19b333");  // (0.1, 0.7, 0.2)
}

TEST_F(CadCliTest, BadFilesAndOptionsExitWithCodeTwo) {
  const auto empty = dir_.write("empty.step", "");
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"parts", empty.string()},
           {"parts", (dir_.path() / "missing.igs").string()},
           {"parts", dir_.write("note.step", "just text\n").string()},
           {"parts", step_.string(), "--angular-deflection", "0"}}) {
    const auto r = run_tandem(args);
    EXPECT_EQ(r.exit_code, 2) << args[1] << ": " << r.err;
    EXPECT_THAT(r.err, HasSubstr("error"));
  }
  EXPECT_THAT(run_tandem({"parts", empty.string()}).err,
              HasSubstr(empty.string() + ": the file is empty"));
}

TEST_F(CadCliTest, AScenarioTakesThePartFromTheAssembly) {
  const auto problem = scenario("peg").string();
  // Straight up out of the pocket, then out sideways between the block and the lid: valid.
  const auto out =
      path_file("out.path", "0 0 0.025 0 0 0 1\n0 0 0.06 0 0 0 1\n0.1 0 0.06 0 0 0 1\n");
  const auto ok = run_tandem({"check-path", problem, out.string()});
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
  // Sideways at once: through the block's wall.
  const auto through = path_file("through.path", "0 0 0.025 0 0 0 1\n0.1 0 0.06 0 0 0 1\n");
  const auto bad = run_tandem({"check-path", problem, through.string()});
  EXPECT_EQ(bad.exit_code, 1) << bad.out << bad.err;
  EXPECT_THAT(bad.out, HasSubstr("the motion from state 0 to state 1 collides"));
  // Up too far: into the lid, a part of a sub-assembly.
  const auto lid = path_file("lid.path", "0 0 0.025 0 0 0 1\n0 0 0.07 0 0 0 1\n");
  const auto into_lid = run_tandem({"check-path", problem, lid.string()});
  EXPECT_EQ(into_lid.exit_code, 1);
  EXPECT_THAT(into_lid.out, HasSubstr("state 1 is in collision"));
}

TEST_F(CadCliTest, ThePlannerTakesThePegOutAndTheWayOutChecksValid) {
  const auto problem = scenario("peg").string();
  const auto path = (dir_.path() / "planned.path").string();
  const auto plan =
      run_tandem({"plan", problem, "--seed", "1", "--time-limit", "60", "--out", path});
  ASSERT_EQ(plan.exit_code, 0) << plan.out << plan.err;
  const auto check = run_tandem({"check-path", problem, path});
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_THAT(check.out, HasSubstr("starts at the start, ends at the goal"));
}

/// The housing's peg taken out with --part: the checks of a path against that problem.
RunResultLine check_take_out(const std::filesystem::path& step, const std::filesystem::path& path,
                             const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args{"check-path", step.string(), path.string(), "--part", "peg"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = run_tandem(args);
  return {r.exit_code, r.out + r.err};
}

TEST_F(CadCliTest, TakeThisPartOutPlansFromTheSeatIntoTheGoalRegion) {
  const auto path = dir_.path() / "out.path";
  const auto plan =
      run_tandem({"plan", step_.string(), "--part", "peg", "--seed", "1", "--out", path.string()});
  ASSERT_EQ(plan.exit_code, 0) << plan.out << plan.err;
  EXPECT_THAT(plan.out, HasSubstr("take peg out of housing: solved"));
  const auto check = check_take_out(step_, path);
  EXPECT_EQ(check.code, 0) << check.text;
  EXPECT_THAT(check.text, HasSubstr("starts at the start, ends in the goal region"));
}

TEST_F(CadCliTest, TheSeatToleranceLetsThePartSlideOutButNotIntoANeighbour) {
  // Seated: touching the pocket's floor. Without a tolerance the start is in collision.
  const auto none = run_tandem({"plan", step_.string(), "--part", "peg", "--seat-tolerance", "0"});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_THAT(none.err, HasSubstr("the start is in collision with obstacle 'housing/base'"));
  // With the default (twice the 0.28 mm deflection): up the pocket, or 0.5 mm toward a wall 1 mm
  // away, is valid; 1 mm into the floor, or 2 mm into a wall, is not.
  const auto up = path_file("up.path", "0 0 0.025 0 0 0 1\n0 0 0.03 0 0 0 1\n");
  EXPECT_EQ(check_take_out(step_, up).code, 0) << check_take_out(step_, up).text;
  const auto slide = path_file("slide.path", "0 0 0.025 0 0 0 1\n0.0005 0 0.025 0 0 0 1\n");
  EXPECT_EQ(check_take_out(step_, slide).code, 0) << check_take_out(step_, slide).text;
  const auto down = path_file("down.path", "0 0 0.025 0 0 0 1\n0 0 0.024 0 0 0 1\n");
  EXPECT_EQ(check_take_out(step_, down).code, 1);
  const auto wall = path_file("wall.path", "0 0 0.025 0 0 0 1\n0.002 0 0.025 0 0 0 1\n");
  EXPECT_EQ(check_take_out(step_, wall).code, 1);
}

TEST_F(CadCliTest, TakeOutOptionsAreCheckedWithOneClearError) {
  auto r = run_tandem({"plan", step_.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--part: name the part to take out"));
  r = run_tandem({"plan", step_.string(), "--part", "housing/lid-1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("no part named 'housing/lid-1'"));  // an assembly, not a part
  r = run_tandem({"plan", "cluttered-1", "--part", "peg"});
  EXPECT_EQ(r.exit_code, 2);
  r = run_tandem({"plan", scenario("peg").string(), "--part", "peg"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--part: takes a part out of a STEP or IGES file"));
  r = run_tandem({"plan", step_.string(), "--part", "peg", "--margin", "-1"});
  EXPECT_EQ(r.exit_code, 2);
}

TEST_F(CadCliTest, ClearanceAlongAWayOutAsTextJsonAndCsv) {
  const auto parts = nlohmann::json::parse(run_tandem({"parts", step_.string(), "--json"}).out);
  const double seat = 2.0 * parts["linear_deflection_m"].get<double>();
  // Up out of the pocket and out between the block and the lid.
  const auto path = path_file("out.path",
                              "0 0 0.025 0 0 0 1\n0 0 0.059 0 0 0 1\n"
                              "0.1 0 0.059 0 0 0 1\n");
  const auto csv = (dir_.path() / "c.csv").string();
  const auto r = run_tandem(
      {"clearance", step_.string(), "--part", "peg", path.string(), "--json", "--csv", csv});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // Seated, the peg's inset bottom is the seating tolerance above the pocket's floor.
  EXPECT_NEAR(j["states"][0]["distance"].get<double>(), seat, 1e-9);
  EXPECT_EQ(j["states"][0]["obstacle"], "housing/base");
  // Leaving the pocket, the peg is a wall's gap (1 mm, plus the tolerance) from the block.
  EXPECT_LE(j["segments"][0]["lower"].get<double>(), 0.001 + seat + 1e-9);
  EXPECT_LE(j["min_clearance"].get<double>(), seat);
  // Out sideways, its inset bottom 4.56 mm above the block (0.059 - 0.015 + the tolerance - 0.04)
  // and its top 6.56 mm under the lid.
  EXPECT_NEAR(j["segments"][1]["lower"].get<double>(), 0.059 - 0.015 + seat - 0.04, 1e-4);
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "kind,from,to,lower,found,at,obstacle");
  int rows = 0;
  while (std::getline(in, line))
    ++rows;
  EXPECT_EQ(rows, 5);  // three states, two motions
  const auto text = run_tandem({"clearance", step_.string(), "--part", "peg", path.string()});
  EXPECT_THAT(text.out, HasSubstr("minimum clearance"));
  EXPECT_THAT(text.out, HasSubstr("near 'housing/base'"));
  EXPECT_EQ(run_tandem({"clearance", step_.string(), "--part", "peg", "nope.path"}).exit_code, 2);
}

TEST_F(CadCliTest, APlanWithAClearanceKeepsItAlongTheWholeWay) {
  const auto path = (dir_.path() / "clear.path").string();
  const auto plan = run_tandem({"plan", step_.string(), "--part", "peg", "--clearance", "0.0004",
                                "--seed", "2", "--out", path});
  ASSERT_EQ(plan.exit_code, 0) << plan.out << plan.err;
  const auto c = run_tandem({"clearance", step_.string(), "--part", "peg", path, "--json"});
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_GE(nlohmann::json::parse(c.out)["min_clearance"].get<double>(), 0.0004);
  const auto check = check_take_out(step_, path, {"--clearance", "0.0004"});
  EXPECT_EQ(check.code, 0) << check.text;
  // Seated 0.56 mm above the pocket's floor: a clearance of 1 mm cannot be kept from the start.
  const auto far = run_tandem({"plan", step_.string(), "--part", "peg", "--clearance", "0.001"});
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_THAT(far.err, HasSubstr("closer than --clearance 0.001"));
  const auto discrete = run_tandem({"plan", step_.string(), "--part", "peg", "--clearance",
                                    "0.0004", "--validation", "discrete"});
  EXPECT_EQ(discrete.exit_code, 2);
  EXPECT_THAT(discrete.err, HasSubstr("needs exact validation"));
}

TEST_F(CadCliTest, AScenarioNamingNoSuchPartOrTwoObjectsExitsWithCodeTwo) {
  auto r = run_tandem(
      {"check-path", scenario("bolt").string(), path_file("p.path", "0 0 0 0 0 0 1\n").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("no part named 'bolt'"));
  EXPECT_THAT(r.err, HasSubstr("housing/peg-spare"));
  r = run_tandem({"check-path", scenario("peg", "[object]\nbox = [1, 1, 1]\n").string(),
                  path_file("p.path", "0 0 0 0 0 0 1\n").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("the object is given twice"));
}

}  // namespace
}  // namespace tandem

namespace tandem {
namespace {

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(ExportCli, AWayOutBecomesAnAnimationAPageAndAnEnvelope) {
  test::TempDir dir;
  const auto step = (dir.path() / "housing.step").string();
  test::write_housing(step);
  const auto path =
      dir.write("out.path", "0 0 0.025 0 0 0 1\n0 0 0.059 0 0 0 1\n0.1 0 0.059 0 0 0 1\n");
  const auto out = [&](const char* name) { return (dir.path() / name).string(); };
  const auto r = test::run_tandem({"export", step, path.string(), "--part", "peg", "--glb",
                                   out("a.glb"), "--html", out("a.html"), "--stl", out("e.stl"),
                                   "--envelope", "--voxel", "0.002"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("contains the part along the whole motion"));
  const std::string glb = file_text(out("a.glb")), page = file_text(out("a.html")),
                    stl = file_text(out("e.stl"));
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_THAT(page, HasSubstr("<title>take peg out of housing: out.path</title>"));
  EXPECT_THAT(page, HasSubstr("id=\"tandem-glb\""));
  EXPECT_GT(page.size(), glb.size() + 100000);  // the glb in base64, and three.js
  ASSERT_GT(stl.size(), 84u);
  std::uint32_t triangles = 0;
  std::memcpy(&triangles, stl.data() + 80, 4);
  EXPECT_GT(triangles, 100u);
  EXPECT_EQ(stl.size(), 84u + 50u * triangles);
}

TEST(ExportCli, BadRequestsExitWithCodeTwoNamingTheFault) {
  test::TempDir dir;
  const auto path = dir.write("p.path", "0 0 0 0 0 0 1\n").string();
  const auto glb = (dir.path() / "a.glb").string();
  auto r = test::run_tandem({"export", "cluttered-1", path});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("nothing to write: give --glb, --html or --stl"));
  r = test::run_tandem({"export", "cluttered-1", path, "--glb", glb, "--duration", "0"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--duration"));
  r = test::run_tandem({"export", "cluttered-1", path, "--stl", glb, "--voxel", "1e-9"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--voxel: too small"));
  r = test::run_tandem({"export", "cluttered-1", "nope.path", "--glb", glb});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("nope.path"));
  r = test::run_tandem(
      {"export", "cluttered-1", path, "--glb", (dir.path() / "no" / "a.glb").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("cannot be written"));
}

}  // namespace
}  // namespace tandem
